-- line: 4
-- expect: plot: unsupported file type '.jpg': use .png, .svg or .pdf
block{ x = {0, 10}, y = {0, 10} }
plot{ file = "picture.jpg" }
