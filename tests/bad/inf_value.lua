-- line: 4
-- expect: zone: edge must be a finite number, got inf
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 1 / 0 }
