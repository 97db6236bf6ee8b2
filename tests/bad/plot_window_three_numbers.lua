-- line: 4
-- expect: plot: window must be four numbers {x0, x1, y0, y1}, got 3
block{ x = {0, 10}, y = {0, 10} }
plot{ file = "picture.png", window = {0, 5, 2} }
