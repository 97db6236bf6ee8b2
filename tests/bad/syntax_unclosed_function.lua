-- line: 8
-- expect: syntax: 'end' expected \(to close 'function' at line 4\) near <eof>
-- The function is never closed; Lua reports <eof> on the line after the last one.
local function cut(angle)
  jset{ angle = angle, spacing = 1 }

cut(30)
