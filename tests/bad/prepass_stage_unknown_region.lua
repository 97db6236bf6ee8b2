-- line: 8
-- expect: prepass: unknown region 'heding' \(did you mean 'heading'\?\)
block{ x = {0, 10}, y = {0, 10} }
region{ name = "heading", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
prepass{ stages = { "heading", "heding" } }
