-- line: 5
-- expect: output: the output file 'run\.vtk' must end in \.xdmf or \.xmf
block{ x = {0, 1}, y = {0, 1} }
zone{ edge = 0.5 }
output{ file = "run.vtk" }
