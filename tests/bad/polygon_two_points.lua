-- line: 3
-- expect: block: outline needs at least 3 vertices, got 2
block{ {0, 0}, {10, 0} }
