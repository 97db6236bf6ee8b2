-- line: 4
-- expect: plot: window must be {x0, x1, y0, y1} with x0 < x1 and y0 < y1, got {0, 5, 6, 2}
block{ x = {0, 10}, y = {0, 10} }
plot{ file = "picture.png", window = {0, 5, 6, 2} }
