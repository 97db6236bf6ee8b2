-- line: 4
-- expect: crackseed: min_angle must be .*60.*, got 75
block{ x = {0, 10}, y = {0, 10} }
crackseed{ angles = {30, 120}, spacing = 1, min_angle = 75 }
