-- line: 3
-- expect: block: item #2 must be a point \{x, y\}, got "corner"
block{ {0, 0}, "corner", {10, 10} }
