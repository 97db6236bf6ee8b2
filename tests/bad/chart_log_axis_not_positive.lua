-- line: 3
-- expect: chart: series 'implicit': y\[3\] = 0 cannot be drawn on the logarithmic y axis: values must be > 0
chart{ file = "speed.svg", log = "y", x_label = "run time [s]",
       series = { { name = "implicit", x = {0.5, 2, 9}, y = {0.02, 0.005, 0} } } }
