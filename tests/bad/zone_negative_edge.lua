-- line: 4
-- expect: zone: edge must be > 0, got -1
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = -1 }
