-- line: 3
-- expect: model: tolerance must be in \(0, 0.001\], got 0
model{ tolerance = 0 }
