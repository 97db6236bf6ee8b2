-- line: 4
-- expect: block: outline is self-intersecting
-- a bow tie: the second and fourth edges cross
block{ {0, 0}, {10, 10}, {10, 0}, {0, 10} }
