-- line: 4
-- expect: crackseed: unknown key 'kn' \(keys: angle, angles, auto, spacing, similar, min_angle, origin, by_mode, region, material, after\)
block{ x = {0, 10}, y = {0, 10} }
crackseed{ angle = 30, spacing = 1, kn = 1e10 }
