-- line: 5
-- expect: insitu: sxx belongs to the stress form; with surface = give density, k0 and surcharge
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
insitu{ surface = 10, density = 2650, k0 = 0.5, sxx = -1e6 }
