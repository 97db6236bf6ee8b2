-- A block 1 micrometre wide took a million zones (4 s, 0.5 GB); refused before meshing.
-- line: 5
-- expect: these zones would be about 1e\+06, more than max_zones = 1e\+06.*blocks no thinner than their zones
block{ x = {0, 1e-6}, y = {0, 1} }
zone{ edge = 0.5 }
