-- line: 3
-- expect: block: unknown key 'xx' \(did you mean 'x'\?\)
block{ xx = {0, 10}, y = {0, 10} }
