-- line: 4
-- expect: crackseed: give angle = a or angles = \{a1, a2\} \(one of them\)
block{ x = {0, 10}, y = {0, 10} }
crackseed{ angle = 30, angles = {30, 120}, spacing = 1 }
