-- line: 4
-- expect: crackseed: kn and ks: compliant potential cracks are not implemented yet
block{ x = {0, 10}, y = {0, 10} }
crackseed{ angle = 30, spacing = 1, kn = 1e10 }
