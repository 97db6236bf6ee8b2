-- line: 4
-- expect: judge: radius must be >= 0, got -1\.5
block{ x = {0, 2}, y = {0, 2} }
judge{ radius = -1.5 }
