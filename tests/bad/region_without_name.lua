-- line: 4
-- expect: region: missing required key 'name'
block{ x = {0, 10}, y = {0, 10} }
region{ polygon = {{2, 2}, {4, 2}, {4, 4}, {2, 4}} }
