-- line: 7
-- expect: excavate: the polygon cuts through block 1 \(it was never cut into the model\)
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
excavate{ region = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
