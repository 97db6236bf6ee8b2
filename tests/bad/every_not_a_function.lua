-- line: 4
-- expect: every: argument #2 \(fn\) must be a function, got "report"
-- a function name in quotes instead of the function
every(100, "report")
