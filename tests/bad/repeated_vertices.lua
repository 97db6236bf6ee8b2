-- line: 3
-- expect: block: outline repeats vertex 2 \(10, 0\)
block{ {0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10} }
