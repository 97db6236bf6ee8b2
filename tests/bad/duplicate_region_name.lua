-- line: 5
-- expect: region: region 'stage1' is already defined
block{ x = {0, 10}, y = {0, 10} }
region{ name = "stage1", polygon = {{2, 2}, {4, 2}, {4, 4}, {2, 4}} }
region{ name = "stage1", polygon = {{6, 6}, {8, 6}, {8, 8}, {6, 8}} }
