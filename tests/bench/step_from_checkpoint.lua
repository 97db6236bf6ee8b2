-- Steps of the seed's cavern from a checkpoint (scripts/paper/case.lua --set save_after=N), solved
-- under a chosen damping, with a point on the rock followed through the solve: what the damping
-- does to a step from the same state (tests/bench/RESULTS.md, "Which walls to believe", "From one
-- state").
--
--   edem --set file=case3_P_h158_none_step14.h5 --set step=warhead_bench_12 --set damping=local \
--        run tests/bench/step_from_checkpoint.lua
--
-- Settings: file (the checkpoint), step (the region to dig, or several separated by commas, dug in
-- turn; "" digs nothing and solves on), on (true: a step short of its ratio is solved on as
-- case.lua does judged at equilibrium: under adaptive damping, 40,000 cycles more to the ratio,
-- then 40,000 to ten times it, and judged there), damping (local, 0.8, adaptive, none, or
-- checkpoint: as saved, with no set{}, the one that follows case.lua's run), release and cycles (the
-- solve's limit past the release), ratio (the solve's goal, 1e-5 as case.lua's steps), the point
-- followed (x, y: the right wall at the springline), every (cycles between the trace's lines),
-- save_to (a checkpoint of the state the solve ends at; "" none), muck (blocks loose at two checks
-- 200 cycles apart are dug out, edem.loose, and rock of steps not yet dug stays, as case.lua's
-- default does), by_contact (N > 0: each contact keeps its own energy balance, energy{ by_contact },
-- and the N that made or lost the most are listed at the end: where an energy error arises),
-- nearest (N > 0: no section breaks, and the N intact ones nearest their strength at the end are
-- listed, each with its overstress, as judge{ most } ranks them: 1 breaks it), neighbours (wait or
-- break: judge{ neighbours } for the steps, judged at equilibrium with judge{}'s other keys at their
-- defaults; "": as the checkpoint has it). The trace gives the energies from the start (slip and
-- damping: what they took), the point's movement and adaptive damping's rate c = 2 omega
-- (info().damping_rate).
local s = settings{ file = "", step = "", damping = "local", release = 100, cycles = 40000, x = 12.0, y = 0.0,
                    every = 2000, save_to = "", muck = true, on = false, by_contact = 0,
                    nearest = 0, neighbours = "", ratio = 1e-5 }
if s.file == "" then error("give --set file=CHECKPOINT.h5", 0) end
restore(s.file)
if s.neighbours ~= "" then judge{ at = "equilibrium", neighbours = s.neighbours } end
-- set{} prepares the model again, which measures afresh a contact whose followed length has strayed
-- more than 10 % from the detection's: "checkpoint" keeps the saved damping and case.lua's path.
if s.damping == "checkpoint" then
  -- as saved
elseif s.damping == "local" then
  set{ damping = "local", local_damping = 0.8 }
elseif s.damping == "adaptive" or s.damping == "none" then
  set{ damping = s.damping }
else
  error(("damping must be local, adaptive, none or checkpoint, got %s"):format(s.damping), 0)
end

local point = gp_near(s.x, s.y)
local function moved()  -- towards the axis, x = 0 [m] (a mucked-out point keeps where it fell)
  for g in gridpoints() do
    if g.id == point.id then return (point.x > 0 and -1 or 1) * (g.ux - point.ux) end
  end
end
if s.by_contact > 0 then energy{ by_contact = true } end
if s.nearest > 0 then judge{ at = "equilibrium", criterion = function() return nil end } end
local start = energy()
local peak = 0
print(("following gridpoint %d at (%.2f, %.2f); damping %s"):format(point.id, point.x, point.y, s.damping))
print(("%8s %9s %11s %11s %11s %9s %10s"):format("cycle", "ratio", "kinetic", "slip", "damping", "moved [m]",
                                                  "c [1/s]"))
every(s.every, function(cycle)
  local e = energy()
  peak = math.max(peak, e.kinetic)
  print(("%8d %9.3g %11.4g %11.4g %11.4g %9.4f %10.3g"):format(cycle, info().ratio, e.kinetic, e.slip - start.slip,
                                                              e.damping - start.damping, moved(), info().damping_rate))
end)
local fallen = 0
if s.muck then
  -- As case.lua: a block goes once it was loose at the check before too, and rock of a cavern step
  -- not dug yet (a block in a warhead_ region other than those dug here) stays for its step.
  local digging, later = {}, {}
  for name in s.step:gmatch("[^,]+") do digging[name] = true end
  for b in blocks() do
    for _, name in ipairs(b.regions) do
      if name:find("^warhead_") and not digging[name] then later[b.id] = true end
    end
  end
  local stays_loose = require("edem.loose").tracker()
  stays_loose(function() return false end)  -- the blocks loose at the checkpoint count as loose before
  every(200, function()
    for _, b in ipairs(stays_loose(function(b, before) return before and not later[b.id] end)) do
      excavate{ block = b.id }
      fallen = fallen + 1
    end
  end)
end
local steps = {}
for name in s.step:gmatch("[^,]+") do steps[#steps + 1] = name end
if #steps == 0 then steps[1] = "" end
for _, name in ipairs(steps) do
  local clock = os.clock()
  if name ~= "" then excavate{ region = name, release = s.release } end
  local r = solve{ ratio = s.ratio, max_cycles = s.release + s.cycles }
  if not r.converged and s.on then
    if s.damping == "local" then set{ damping = "adaptive" } end
    for _, ratio in ipairs{ s.ratio, 10 * s.ratio } do
      local again = solve{ ratio = ratio, max_cycles = 40000 }
      r.cycles, r.converged, r.ratio = r.cycles + again.cycles, again.converged, again.ratio
      if again.converged then break end
    end
    if s.damping == "local" then set{ damping = "local", local_damping = 0.8 } end
  end
  print(("%s%s: %s after %d cycles (ratio %.3g), %d cracks, %d blocks mucked out; the point moved %.4f m "
         .. "towards the axis; kinetic energy at most %.4g J/m (at the trace's lines); %.0f s"):format(
         name ~= "" and name .. ", " or "", s.damping, r.converged and "converged" or "NOT converged", r.cycles,
         r.ratio, info().cracks, fallen, moved(), peak, os.clock() - clock))
end
if s.by_contact > 0 then
  local made = {}
  for c in contacts() do made[#made + 1] = c end
  table.sort(made, function(a, b) return math.abs(a.energy_made) > math.abs(b.energy_made) end)
  local e = energy()
  print(("energy error since the checkpoint %.4g J/m, %.4g of it in the contacts; the contacts that made most:"):format(
    e.error - start.error, e.contact_error - start.contact_error))
  for i = 1, math.min(s.by_contact, #made) do
    local c = made[i]
    print(("  contact %d, %s, %s, gridpoint of block %d at (%.2f, %.2f) on block %d: made %.4g J/m; fn %.4g N/m over "
           .. "%.4g m, overlap %.4g m, shear displacement %.4g m, slip %.4g m"):format(c.id, c.kind, c.state, c.block,
           c.x, c.y, c.other, c.energy_made, c.fn, c.length, c.overlap, c.us, c.slip))
  end
end
if s.nearest > 0 then
  local broken, near = {}, {}
  for k in cracks() do broken[k.section] = true end
  for sec in sections() do
    if not sec.gone and not broken[sec.id] then
      near[#near + 1] = { id = sec.id, x = sec.x, y = sec.y, share = sec.overstress, s1 = sec.s1, s3 = sec.s3 }
    end
  end
  table.sort(near, function(a, b) return a.share > b.share end)
  print("the intact sections nearest their strength (none was let break):")
  for i = 1, math.min(s.nearest, #near) do
    local n = near[i]
    print(("  section %d at (%.2f, %.2f): %.3f of its strength; s1 %.3g, s3 %.3g MPa"):format(n.id, n.x, n.y, n.share,
                                                                                           n.s1 / 1e6, n.s3 / 1e6))
  end
end
if s.save_to ~= "" then save(s.save_to) end
