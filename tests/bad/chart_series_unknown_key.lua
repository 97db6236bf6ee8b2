-- line: 3
-- expect: chart: series\[2\]: unknown key 'names' \(did you mean 'name'\?\): a series has name, x and y
chart{ file = "speed.png", series = { { name = "a", x = {1, 2}, y = {3, 4} }, { names = "b", x = {1}, y = {2} } } }
