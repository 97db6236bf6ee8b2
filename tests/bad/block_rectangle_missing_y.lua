-- line: 3
-- expect: block: a rectangle needs both x = \{x0, x1\} and y = \{y0, y1\}
block{ x = {0, 10} }
