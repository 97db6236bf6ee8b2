-- line: 3
-- expect: block: give corner points or x = \{x0, x1\}, y = \{y0, y1\}, not both
block{ {0, 0}, {10, 0}, {10, 10}, x = {0, 10} }
