-- line: 4
-- expect: jset: angle must be in \[-360, 360\], got 400
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 400, spacing = 1 }
