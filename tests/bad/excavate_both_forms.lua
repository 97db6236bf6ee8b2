-- line: 8
-- expect: excavate: both given: give the region as item 1 or as region =
block{ x = {0, 10}, y = {0, 10} }
region{ name = "stage1", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
excavate{ "stage1", region = "stage1" }
