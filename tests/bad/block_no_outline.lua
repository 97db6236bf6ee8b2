-- line: 3
-- expect: block: no outline: give corner points
block{}
