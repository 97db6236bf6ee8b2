-- line: 4
-- expect: crack: crack from \(1, 1\) to \(1, 1\) has zero length
block{ x = {0, 10}, y = {0, 10} }
crack{ from = {1, 1}, to = {1, 1} }
