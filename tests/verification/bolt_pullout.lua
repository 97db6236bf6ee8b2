-- Pull-out of a fully grouted bolt from rigid ground: the shear-lag closed form of a bolt whose
-- grout is a spring-slider (Itasca's cable element; the exponential decay of a long bolt's load
-- is Farmer's, 1975, IJRMMS 12:347-351).
--
-- Closed form (elastic bond, free far end), x from the loaded head:
--   lambda = sqrt(k_b / EA), F(x) = F0 sinh(lambda (L - x)) / sinh(lambda L),
--   K_head = EA lambda tanh(lambda L), slip starts at F0 = (s_b / lambda) tanh(lambda L),
--   capacity min(s_b L, F_y).
-- Reference values: the seed's bolt (the seed paper, Jiang et al., §4.2: E = 190 GPa,
-- A = 446 mm^2) in a reference grout, k_b = 50 MN/m/m, s_b = 0.2 MN/m; one bolt per metre of
-- thickness (spacing 1), so the model's forces are the bolt's.
--
-- Set-up: a thin strip of rock whose every gridpoint is held (the rigid host), the bolt laid along
-- its axis with 40 grouted segments from the hole's mouth (x = 0) to x = L, and a free tail of
-- 0.1 m out of the hole where the jack grips it (bolt{ free_length }): the jack's load is then the
-- steel's force at the mouth, as in the closed form. The jack pulls the head out of the hole at a
-- slow velocity (bolt_head{ velocity }: in static mode, m per cycle; slow enough that the loads
-- ahead of the head keep up with it), stopping now and then to hold and solve to equilibrium,
-- where the load is read.
--   1. L = 5 m, elastic: F(x) along the bolt at F0 = 0.5 of the slip onset, within 2 % of F0;
--      head stiffness F0 / u0 (u0 at the mouth) within 1 %.
--   2. L = 0.5 m (s_b L = 100 kN < F_y): the load rises to the bond's capacity s_b L and stays
--      there as the head is pulled on (peak and plateau within 1 %); no segment yields. Pulled
--      12 mm, three times the head displacement at full debonding: the closed form is for small
--      displacements, and a bolt node drawn out of the hole (beyond a quarter of a zone) loses its
--      grout, so pulled much further the plateau steps down by s_b dx / 2 per node that leaves.
--   3. L = 5 m with F_y = 0.156 MN (the seed's bolt): the load stops at F_y (within 1 %), the bolt
--      yielding at the mouth before the bond can fail (s_b L = 1 MN).
local check = require "edem.check"

local EA_E, AREA = 190e9, 446e-6
local KB, SB, FY = 50e6, 0.2e6, 0.156e6
local EA = EA_E * AREA
local LAMBDA = math.sqrt(KB / EA)
local RATIO = 1e-9
local TAIL = 0.1      -- free length out of the hole [m]
local SPEED = 1e-8    -- the jack [m per cycle]: 68 N per cycle on the mouth's segment

-- A rigid strip 0.1 m thick with the bolt along y = 0 from (0, 0) to (L, 0); returns the bolt id.
local function setup(length, yield)
  model{ title = ("pull-out, L = %g m"):format(length) }
  block{ x = { 0, length + 0.5 }, y = { -0.05, 0.05 } }
  zone{ edge = 0.25 }
  material{ "rock", young = 30e9, poisson = 0.25, density = 2600 }
  assign{ material = "rock" }
  boundary{ polygon = { { -1, -1 }, { length + 1, -1 }, { length + 1, 1 }, { -1, 1 } }, fix = "xy" }
  for g in gridpoints() do
    assert(g.fixed_x and g.fixed_y, "the host must be rigid: every gridpoint held")
  end
  bolt_material{ "bolt", young = EA_E, area = AREA, yield_tension = yield, failure_strain = 0.5,
                 bond_stiffness = KB, bond_strength = SB }
  return bolt{ from = { -TAIL, 0 }, to = { length, 0 }, free_length = TAIL, segments = 40, material = "bolt" }
end

local function the_bolt() for b in bolts() do return b end end

-- Pulls the head out by `du` [m] at the jack's speed, then holds it and solves; returns the load.
local function pull(id, du)
  local n = math.max(1, math.ceil(du / SPEED))
  bolt_head{ bolt = id, velocity = du / n }
  cycle(n)
  bolt_head{ bolt = id, velocity = 0 }
  local r = solve{ ratio = RATIO, max_cycles = 200000 }
  assert(r.converged, ("pull step did not converge: ratio %g"):format(r.ratio))
  return the_bolt().head_force
end

-- The mouth's displacement outwards [m]: the grouted part's first node.
local function mouth_u(b) return -b.segments[2].a.x end

-- 1. Elastic: F(x) and the head stiffness at half the slip-onset load.
do
  local L = 5.0
  local id = setup(L, 10 * FY)
  local onset = SB / LAMBDA * math.tanh(LAMBDA * L)
  local k_head = EA * LAMBDA * math.tanh(LAMBDA * L)
  local target = 0.5 * onset / k_head  -- head displacement for F0 = onset / 2
  pull(id, target)
  local b = the_bolt()
  local F0, u0 = b.head_force, mouth_u(b)
  local grouted = #b.segments - 1
  print(("elastic: F0 = %.6g N at u0 = %.6g m (%d grouted segments)"):format(F0, u0, grouted))
  check.report("5 m elastic: the jack's load = the free tail's force", F0, b.segments[1].force, 1e-9)
  local worst, at = 0, 0
  for i = 2, #b.segments do
    local s = b.segments[i]
    local x = (i - 1.5) * L / grouted
    local closed = F0 * math.sinh(LAMBDA * (L - x)) / math.sinh(LAMBDA * L)
    local err = math.abs(s.force - closed) / F0
    if err > worst then worst, at = err, x end
  end
  print(("  worst F(x) error at x = %.4g m"):format(at))
  check.report("5 m elastic: F(x) along the bolt, worst / F0", worst, 0, 0.02, { absolute = true })
  for _, x in ipairs({ 1.25, 2.5, 3.75 }) do
    local i = math.floor(x / (L / grouted)) + 1  -- grouted segment i (segments[i + 1]) starts at x
    local s0, s1 = b.segments[i], b.segments[i + 1]
    local f = 0.5 * (s0.force + s1.force)  -- at the node between them
    check.report(("5 m elastic: F/F0 at x = %.2f m"):format(x), f / F0,
                 math.sinh(LAMBDA * (L - x)) / math.sinh(LAMBDA * L), 0.02)
  end
  check.report("5 m elastic: head stiffness F0 / u0 [N/m]", F0 / u0, k_head, 0.01)
  check.report("5 m elastic: no grout slipping", b.segments[2].plastic_slip, 0, 1e-12, { absolute = true })
end

-- Pulls in steps of `du` to `total` and returns the peak and the last load.
local function pull_out(id, total, du)
  local peak, last, u = 0, 0, 0
  while u < total - 1e-12 do
    last = pull(id, du)
    u = u + du
    peak = math.max(peak, last)
  end
  print(("  pulled %.4g m in %d cycles"):format(total, info().cycle))
  return peak, last
end

-- 2. Bond failure: L = 0.5 m, capacity s_b L = 100 kN below the yield force.
do
  local L = 0.5
  local id = setup(L, FY)
  local capacity = SB * L
  local peak, last = pull_out(id, 0.012, 0.0005)
  local b = the_bolt()
  print(("0.5 m: peak %.6g N, last %.6g N, head slip %.4g m, yielded segments %d"):format(
    peak, last, b.segments[1].slip, b.yielded))
  check.report("0.5 m bond failure: peak load / s_b L", peak, capacity, 0.01)
  check.report("0.5 m bond failure: post-peak plateau / s_b L", last, capacity, 0.01)
  check.report("0.5 m bond failure: no segment yielded", b.yielded, 0, 0, { absolute = true })
end

-- 3. Bolt yield: L = 5 m with the seed's F_y; s_b L = 1 MN would need far more.
do
  local L = 5.0
  local id = setup(L, FY)
  local peak, last = pull_out(id, 0.012, 0.0005)
  local b = the_bolt()
  print(("5 m: peak %.6g N, last %.6g N, yielded segments %d, largest strain %.4g"):format(
    peak, last, b.yielded, b.segments[1].strain))
  check.report("5 m bolt yield: peak load / F_y", peak, FY, 0.01)
  check.report("5 m bolt yield: post-peak plateau / F_y", last, FY, 0.01)
  check.report("5 m bolt yield: the head segment yielded", b.segments[1].state == "yielded" and 1 or 0, 1, 0,
               { absolute = true })
end

check.finish()
