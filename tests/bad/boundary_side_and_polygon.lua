-- line: 5
-- expect: boundary: give side or polygon, not both
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
boundary{ side = "top", polygon = {{-1, 9}, {11, 9}, {11, 11}, {-1, 11}}, fix = "y" }
