-- How many potential-crack sections crackseed{ auto } lays on one prepass as its grid of cuts
-- moves: each group's cuts through its own centroid (case.lua's default), or every group's through
-- one fixed point (case.lua's origin_x, origin_y), at the seed's spacing (4.8 m) and at half of it.
-- The same yielded zones each time, so what changes is the placement alone (the README, "What
-- would change the verdicts": the placement of potential cracks).
--
--   edem --quiet --threads 2 run scripts/paper/cut_phase.lua   (--set case=1, 2 or 3 [3])
--
-- About 4 minutes on two threads, most of it the jointed prepass (edem.yield_pass, as case.lua's).
local seed = require "edem.seed"
local cavern = require "edem.cavern"
local yield_pass = require "edem.yield_pass"

local given = settings{ case = 3 }
local c = cavern.warhead{}
local function build()
  seed.region{ case = given.case, set = "P", depth = 158, regions = c.stages, near = { c.outline }, edge = 1.5,
               far = 10, tolerance = 7e-4 }
  seed.intact("P")
end
build()
local names = {}
for _, s in ipairs(c.stages) do names[#names + 1] = s.name end
local pre = yield_pass.run{ stages = names, release = 3000, damping = "local" }

print(("%-9s %-14s %7s %9s %11s"):format("spacing", "cuts through", "groups", "sections", "length [m]"))
for _, spacing in ipairs{ 4.8, 2.4 } do
  for _, origin in ipairs{ "centroid", { 1.22, 0.34 }, { 3.6, 2.0 }, { -2.0, 1.1 } } do
    build()
    yield_pass.check(pre)
    local groups = crackseed{ auto = pre, spacing = spacing, material = "intact", similar = 45, min_angle = 30,
                              origin = origin ~= "centroid" and origin or nil }
    local length = 0
    for s in sections() do length = length + s.length end
    local through = origin == "centroid" and "each centroid" or ("(%g, %g)"):format(origin[1], origin[2])
    print(("%-9s %-14s %7d %9d %11.1f"):format(("%.1f m"):format(spacing), through, #groups, info().sections, length))
  end
end
