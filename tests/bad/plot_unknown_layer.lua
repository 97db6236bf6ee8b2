-- line: 4
-- expect: plot: show\[2\] must be one of .*, got "block" \(did you mean 'blocks'\?\)
block{ x = {0, 10}, y = {0, 10} }
plot{ file = "bad_layer.png", show = {"zones", "block"} }
