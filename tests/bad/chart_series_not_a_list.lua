-- line: 4
-- expect: chart: series must be a list of series, like \{\{name = "\.\.\.", x = \{\.\.\.\}, y = \{\.\.\.\}\}\}: one series needs braces of its own
local runs = { name = "implicit", x = {0.5, 2, 9}, y = {0.02, 0.005, 0.001} }
chart{ file = "speed.pdf", series = runs }
