-- line: 9
-- expect: excavate: region 'stage1' was excavated already \(stage 1\)
block{ x = {0, 10}, y = {0, 10} }
region{ name = "stage1", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
excavate("stage1")
excavate{ region = "stage1" }
