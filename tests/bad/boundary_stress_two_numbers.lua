-- line: 5
-- expect: boundary: stress must be \{sxx, syy, sxy\} or "insitu", got 2 numbers
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
boundary{ side = "top", stress = {0, -1e6} }
