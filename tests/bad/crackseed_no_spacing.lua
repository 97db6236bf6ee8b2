-- line: 4
-- expect: crackseed: spacing is needed
block{ x = {0, 10}, y = {0, 10} }
crackseed{ angle = 30 }
