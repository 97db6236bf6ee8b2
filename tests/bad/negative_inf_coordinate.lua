-- line: 3
-- expect: block: x\[1\] must be a finite number, got -inf
block{ x = {-math.huge, 0}, y = {0, 10} }
