-- A region's corner at 3e307 m (a crash in CGAL's sweep) is refused at its line.
-- line: 5
-- expect: polygon vertex 2 \(3e\+307, 0\) is beyond 1e\+07 m
block{ x = {-10, 10}, y = {-10, 10} }
region{ name = "r", polygon = {{0, 0}, {3e307, 0}, {0, 1}} }
