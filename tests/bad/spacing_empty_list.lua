-- line: 4
-- expect: jset: spacing must not be an empty list
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 30, spacing = {} }
