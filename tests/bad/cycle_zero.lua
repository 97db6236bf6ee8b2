-- line: 3
-- expect: cycle: argument #1 \(n\) must be >= 1, got 0
cycle(0)
