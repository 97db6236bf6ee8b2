-- line: 3
-- expect: cycle: argument #1 \(n\) must be in \[1, 1000000000000\], got 0
cycle(0)
