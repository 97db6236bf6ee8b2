-- A joint set's origin very many spacings from the blocks (at 1e12 m, laying its lines from there
-- took 2 GB and ran out of memory): refused at once, with what to do.
-- line: 6
-- expect: origin \(0, 9e\+06\) is 9e\+06 m from the blocks, 1.8e\+07 spacings
block{ x = {-10, 10}, y = {-10, 10} }
jset{ angle = 30, origin = {0, 9e6}, spacing = 0.5 }
