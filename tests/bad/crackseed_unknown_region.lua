-- line: 5
-- expect: crackseed: unknown region 'arc' \(did you mean 'arch'\?\)
block{ x = {0, 10}, y = {0, 10} }
region{ name = "arch", polygon = {{2, 2}, {8, 2}, {8, 8}, {2, 8}} }
crackseed{ angle = 30, spacing = 1, region = "arc" }
