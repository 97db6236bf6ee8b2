-- line: 4
-- expect: jset: missing required key 'spacing'
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 30 }
