-- line: 4
-- expect: jset: angle must be a finite number, got nan
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 0 / 0, spacing = 1 }
