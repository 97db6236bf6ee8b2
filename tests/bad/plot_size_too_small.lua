-- line: 4
-- expect: plot: size\[1\] must be in \[64, 16384\], got 10
block{ x = {0, 10}, y = {0, 10} }
plot{ file = "tiny.png", size = {10, 10} }
