-- line: 4
-- expect: crackseed: min_angle is for auto = a prepass\{\} result: cuts at angle or angles are laid as given
block{ x = {0, 10}, y = {0, 10} }
crackseed{ angles = {30, 120}, spacing = 1, min_angle = 20 }
