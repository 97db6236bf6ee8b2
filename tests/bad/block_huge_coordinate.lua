-- A coordinate far beyond any rock mass (1e200 m overflowed the exact geometry: SIGFPE in GMP
-- once a region was cut) is refused at its line.
-- line: 5
-- expect: block vertex [0-9]+ \(.*1e\+200\) is beyond 1e\+07 m
block{ x = {-10, 10}, y = {-10, 1e200} }
region{ name = "r", polygon = {{0, 0}, {1, 0}, {1, 1}} }
