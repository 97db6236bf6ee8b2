-- line: 4
-- expect: jset: unknown region 'weak'
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 45, spacing = 1, region = "weak" }
