-- line: 4
-- expect: syntax: unexpected symbol near '='
block{ x = {0, 10}, y = {0, 10} }
local spacing = = 2
