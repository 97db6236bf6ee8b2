-- line: 9
-- expect: excavate: unknown region 'tunnel' \(there are: heading, bench\)
block{ x = {0, 10}, y = {0, 10} }
region{ name = "heading", polygon = {{4, 5}, {6, 5}, {6, 6}, {4, 6}} }
region{ name = "bench", polygon = {{4, 4}, {6, 4}, {6, 5}, {4, 5}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
excavate("tunnel")
