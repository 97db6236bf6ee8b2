-- line: 4
-- expect: info: takes no arguments, got 1
block{ x = {0, 10}, y = {0, 10} }
print(info("blocks"))
