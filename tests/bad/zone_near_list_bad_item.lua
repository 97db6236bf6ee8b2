-- line: 5
-- expect: zone: near\[2\] must be a region name or a polygon, got 5
block{ x = {0, 10}, y = {0, 10} }
region{ name = "roof", polygon = {{2, 2}, {8, 2}, {8, 8}, {2, 8}} }
zone{ edge = 1, near = {"roof", 5} }
