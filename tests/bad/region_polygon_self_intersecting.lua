-- line: 4
-- expect: region: polygon is self-intersecting
block{ x = {0, 10}, y = {0, 10} }
region{ name = "stage1", polygon = {{2, 2}, {8, 8}, {8, 2}, {2, 8}} }
