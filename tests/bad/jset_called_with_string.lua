-- line: 4
-- expect: jset: expects a table, like jset\{ angle = ..., spacing = ..., ... \}, got "60"
block{ x = {0, 10}, y = {0, 10} }
jset "60"
