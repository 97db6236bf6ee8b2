-- line: 4
-- expect: judge: radius must be a finite number, got inf
block{ x = {0, 2}, y = {0, 2} }
judge{ radius = math.huge }
