-- line: 5
-- expect: cycle: .*material
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
cycle(10)
