-- line: 17
-- expect: prepass: stage 1 \(hole\): the prepass's time budget of 2 s ran out at load factor [0-9.e-]+ .*prepass\{ seconds = \.\.\. \} gives it more
-- A prepass with a time budget it cannot keep stops at the Newton iteration running, naming the
-- stage, the load factor and the budget, instead of running on without bound.
local shapes = require "edem.shapes"
block{ x = {0, 40}, y = {0, 40} }
region{ name = "hole", polygon = shapes.circle{ centre = {20, 20}, radius = 4, segments = 32 } }
zone{ edge = 0.5, near = { "hole" }, far = 2 }
material{ "rock", model = "mohr", density = 2500, young = 2e9, poisson = 0.25, cohesion = 1e5, friction = 30,
          tension = 1e4 }
assign{ material = "rock" }
insitu{ sxx = -5e6, syy = -5e6, szz = -5e6 }
boundary{ side = "left", fix = "x" }
boundary{ side = "right", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "top", fix = "y" }
prepass{ stages = { "hole" }, seconds = 2 }
