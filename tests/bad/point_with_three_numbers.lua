-- line: 4
-- expect: jset: origin must be a point \{x, y\}, got a table with 3 items
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 0, spacing = 1, origin = {1, 2, 3} }
