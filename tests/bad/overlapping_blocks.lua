-- line: 4
-- expect: block: block overlaps block 1
block{ x = {0, 10}, y = {0, 10} }
block{ x = {5, 15}, y = {0, 10} }
