-- line: 3
-- expect: block: y must be \{y0, y1\} with y0 < y1, got \{10, 0\}
block{ x = {0, 10}, y = {10, 0} }
