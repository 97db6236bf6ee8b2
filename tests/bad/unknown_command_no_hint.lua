-- line: 4
-- expect: frobnicate: unknown command[^(]*$
block{ x = {0, 10}, y = {0, 10} }
frobnicate{ level = 3 }
