-- line: 4
-- expect: jset: angle_dev must be in \[0, 90\], got -5
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 10, spacing = 1, angle_dev = -5 }
