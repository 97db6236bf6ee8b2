-- line: 4
-- expect: region: glued must be true or false, got "yes"
block{ x = {0, 10}, y = {0, 10} }
region{ name = "a", polygon = {{2, 2}, {4, 2}, {4, 4}, {2, 4}}, glued = "yes" }
