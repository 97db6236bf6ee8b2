-- A function that calls itself without end: Lua's stack overflow, said at once (its traceback
-- shows the first and last frames), never a hang.
-- line: 6
-- expect: stack overflow.*\.\.\. \([0-9][0-9][0-9][0-9]+ more\)
local f
f = function(n) return f(n + 1) + 1 end
f(1)
