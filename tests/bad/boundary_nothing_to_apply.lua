-- line: 5
-- expect: boundary: nothing to apply: give stress, fix, free, xvel or yvel
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
boundary{ side = "left" }
