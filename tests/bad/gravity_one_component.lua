-- line: 3
-- expect: gravity: missing item #2 \(gy\)
gravity{ -9.81 }
