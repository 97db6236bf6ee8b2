-- A joint set's origin far from the blocks (at 1e12 m, laying its lines from there took 2 GB and ran
-- out of memory): refused at once, with what to do.
-- line: 6
-- expect: origin \(0, 1e\+06\) is 1e\+06 m from the blocks, which are 28.3 m across
block{ x = {-10, 10}, y = {-10, 10} }
jset{ angle = 30, spacing = 1, origin = {0, 1e6} }
