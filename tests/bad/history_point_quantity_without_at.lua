-- line: 3
-- expect: history: uy is measured at a point: give at = \{x, y\}
history{ "uy" }
