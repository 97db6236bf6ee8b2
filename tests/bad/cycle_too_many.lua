-- line: 10
-- expect: cycle: argument #1 \(n\) must be in \[1, 1000000000000\], got 900719925474099
-- A cycle count no run could finish (a stray digit) is refused at once instead of cycling on.
block{ x = {0, 2}, y = {0, 1} }
zone{ edge = 0.5 }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "xy" }
gravity{ 0, -9.81 }
cycle(9007199254740993)
