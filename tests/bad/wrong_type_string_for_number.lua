-- line: 4
-- expect: jset: angle must be a number, got "60"
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = "60", spacing = 1 }
