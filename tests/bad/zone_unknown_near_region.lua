-- line: 5
-- expect: zone: unknown region 'rof' \(did you mean 'roof'\?\)
block{ x = {0, 10}, y = {0, 10} }
region{ name = "roof", polygon = {{2, 2}, {8, 2}, {8, 8}, {2, 8}} }
zone{ edge = 1, near = "rof" }
