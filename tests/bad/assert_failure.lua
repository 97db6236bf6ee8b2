-- line: 4
-- expect: error: expected more than 5 blocks
block{ x = {0, 10}, y = {0, 10} }
assert(info().blocks > 5, "expected more than 5 blocks")
