-- line: 4
-- expect: jset: spacing\[2\] must be > 0, got 0
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 30, spacing = {2, 0, 1} }
