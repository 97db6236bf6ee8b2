-- line: 5
-- expect: output: give every or at, not both
block{ x = {0, 1}, y = {0, 1} }
zone{ edge = 0.5 }
output{ file = "run.xdmf", every = 100, at = "stage" }
