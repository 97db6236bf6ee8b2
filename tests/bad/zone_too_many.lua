-- Zones far too small for the blocks are refused before meshing, with the estimate.
-- line: 5
-- expect: these zones would be about 2.31e\+08, more than max_zones = 1e\+06
block{ x = {0, 1}, y = {0, 1} }
zone{ edge = 1e-4 }
