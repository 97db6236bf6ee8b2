-- line: 5
-- expect: restore: cannot read checkpoint 'no_such_file\.h5': no such file
block{ x = {0, 1}, y = {0, 1} }
zone{ edge = 0.5 }
restore("no_such_file.h5")
