-- line: 4
-- expect: plot: show must be a string or a list of strings, got 3
block{ x = {0, 10}, y = {0, 10} }
plot{ file = "bad_show.png", show = 3 }
