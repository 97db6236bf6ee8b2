-- The same inside an every() callback: said at once, at the callback's line.
-- line: 8
-- expect: stack overflow
block{ x = {0, 1}, y = {0, 1} }
zone{ edge = 0.5 }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
local function deeper(n) return deeper(n + 1) + 1 end
every(1, function() deeper(1) end)
cycle(2)
