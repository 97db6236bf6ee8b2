-- line: 4
-- expect: jset: spacing must be > 0, got -2
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 30, spacing = -2 }
