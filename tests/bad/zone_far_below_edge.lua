-- line: 4
-- expect: zone: far must be >= edge \(2\), got 1
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2, far = 1 }
