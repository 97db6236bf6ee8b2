-- line: 4
-- expect: zone: unknown key 'colour' \(keys: edge, far, growth, near, region, sliver, max_zones\)
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 1, colour = "red" }
