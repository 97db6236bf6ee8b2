-- line: 8
-- expect: excavate: unknown region 'stage_1' \(did you mean 'stage1'\?\)
block{ x = {0, 10}, y = {0, 10} }
region{ name = "stage1", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
excavate("stage_1")
