-- line: 4
-- expect: jset: seed must be >= 0, got -3
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 30, spacing = 1, angle_dev = 5, seed = -3 }
