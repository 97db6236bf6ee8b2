-- One step of the seed's cavern dug from one state at several releases, each solved on to a tight
-- ratio with no section let break: how far apart the equilibria they end at lie, against the
-- slowest release's (tests/bench/RESULTS.md, "One step from the in-situ state"). What moves is
-- the joints: the contacts that slipped on the way are counted.
--
--   edem --set case=3 --set save_after=0 run scripts/paper/case.lua   # case3_P_h158_none_step0.h5
--   edem --set file=case3_P_h158_none_step0.h5 run tests/bench/release_paths.lua
--
-- Settings: file (a checkpoint: case.lua --set save_after=N), step (the region to dig), releases
-- (cycles, separated by commas; the last is the reference), damping (local, 0.8, or adaptive),
-- ratio (the solve's; case.lua's steps stop at 1e-5), settle (> 0: then solved on to this ratio
-- under adaptive damping; 0: not), cycles (each solve's limit past the release), within (m:
-- gridpoints this far from the origin are compared), friction (deg > 0: the joints' friction
-- raised to this, Set P's joint law kept, so that closed joints cannot slip; 0: as they are).
local s = settings{ file = "", step = "warhead_arch_centre", releases = "1,100,1000,3000,10000,30000",
                    damping = "local", ratio = 1e-7, settle = 0, cycles = 400000, within = 60, friction = 0 }
if s.file == "" then error("give --set file=CHECKPOINT.h5 (case.lua --set save_after=0)", 0) end
if s.damping ~= "local" and s.damping ~= "adaptive" then
  error(("damping must be local or adaptive, got %s"):format(s.damping), 0)
end
local releases = {}
for r in tostring(s.releases):gmatch("[^,]+") do
  local n = math.tointeger(tonumber(r))
  if not (n and n >= 1) then error(("releases must be whole numbers of cycles >= 1, got %s"):format(r), 0) end
  releases[#releases + 1] = n
end

-- The state each release ends at: every gridpoint's displacement, and the contacts that slipped.
local function dig(release)
  restore(s.file)
  if s.damping == "local" then set{ damping = "local", local_damping = 0.8 } else set{ damping = "adaptive" } end
  judge{ at = "equilibrium", criterion = function() return nil end }
  if s.friction > 0 then
    local joint = require("edem.seed").P.joint
    joint_material{ "joint", kn_law = joint.kn_law, stress_scale = joint.stress_scale,
                    closure_scale = joint.closure_scale, ks = joint.ks, friction = s.friction }
  end
  excavate{ region = s.step, release = release }
  local r = solve{ ratio = s.ratio, max_cycles = release + s.cycles }
  if s.settle > 0 then
    set{ damping = "adaptive" }
    local more = solve{ ratio = s.settle, max_cycles = s.cycles }
    r = { cycles = r.cycles + more.cycles, ratio = more.ratio }
  end
  local u = {}
  for g in gridpoints() do
    if math.sqrt(g.x ^ 2 + g.y ^ 2) <= s.within then u[g.id] = { g.ux, g.uy } end
  end
  local slipped = 0
  for c in contacts() do if c.slip > 0 then slipped = slipped + 1 end end
  return { release = release, cycles = r.cycles, ratio = r.ratio, u = u, slipped = slipped }
end

local runs = {}
for i, release in ipairs(releases) do runs[i] = dig(release) end
local reference = runs[#runs]
print(("%s dug from %s under %s damping, solved to %g%s; each against the release over %d cycles"):format(
  s.step, s.file, s.damping, s.ratio, s.settle > 0 and (" and on to %g under adaptive damping"):format(s.settle) or "",
  reference.release))
print(("%9s %8s %9s %8s %13s %11s %12s"):format("release", "cycles", "ratio", "slipped", "largest [mm]",
                                                "rms [mm]", "moved [mm]"))
for _, run in ipairs(runs) do
  local largest, sum, n, moved = 0, 0, 0, 0
  for id, u in pairs(run.u) do
    local v = reference.u[id]
    if v then
      local d = math.sqrt((u[1] - v[1]) ^ 2 + (u[2] - v[2]) ^ 2)
      largest, sum, n = math.max(largest, d), sum + d * d, n + 1
      moved = math.max(moved, math.sqrt(v[1] ^ 2 + v[2] ^ 2))
    end
  end
  print(("%9d %8d %9.3g %8d %13.4f %11.4f %12.2f"):format(run.release, run.cycles, run.ratio, run.slipped,
                                                        1e3 * largest, 1e3 * math.sqrt(sum / math.max(n, 1)),
                                                        1e3 * moved))
end
