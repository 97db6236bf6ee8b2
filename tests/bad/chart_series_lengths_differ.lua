-- line: 3
-- expect: chart: series 'explicit': x has 3 values but y has 2
chart{ file = "speed.png", log = {"x", "y"},
       series = { { name = "implicit", x = {0.5, 2, 9}, y = {0.02, 0.005, 0.001} },
                  { name = "explicit", x = {3, 20, 90}, y = {0.03, 0.01} } } }
