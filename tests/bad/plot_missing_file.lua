-- line: 4
-- expect: plot: missing required key 'file'
block{ x = {0, 10}, y = {0, 10} }
plot{ show = "blocks" }
