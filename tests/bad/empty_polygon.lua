-- line: 4
-- expect: region: polygon needs at least 3 vertices, got 0
block{ x = {0, 10}, y = {0, 10} }
region{ name = "empty", polygon = {} }
