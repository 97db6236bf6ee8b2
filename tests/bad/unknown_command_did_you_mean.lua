-- line: 4
-- expect: blok: unknown command \(did you mean 'block'\?\)
model{ title = "typo in a command name" }
blok{ x = {0, 10}, y = {0, 10} }
