-- line: 4
-- expect: zone: no blocks to zone: define blocks with block\{...\} first
model{ title = "nothing to zone" }
zone{ edge = 1 }
