-- line: 3
-- expect: solve: ratio must be in \(0, 1\), got 0
solve{ ratio = 0 }
