-- line: 4
-- expect: region: polygon\[2\]\[2\] must be a number, got "two"
block{ x = {0, 10}, y = {0, 10} }
region{ name = "a", polygon = {{2, 2}, {8, "two"}, {5, 8}} }
