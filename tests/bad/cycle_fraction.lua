-- line: 3
-- expect: cycle: argument #1 \(n\) must be an integer, got 1\.5
cycle(1.5)
