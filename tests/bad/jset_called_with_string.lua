-- line: 4
-- expect: jset: expects a table, like jset\{ angle = 60, spacing = \{16, 12, 8\} \}, got "60"
block{ x = {0, 10}, y = {0, 10} }
jset "60"
