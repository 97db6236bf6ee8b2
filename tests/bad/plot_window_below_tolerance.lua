-- line: 6
-- expect: plot: window is 1.78e-15 m by 1.78e-15 m, smaller than the model's geometric tolerance, [0-9.e-]+ m: nothing in it could be told apart
-- A window far below what the model can tell apart is refused at once (its axis ticks, added up
-- step by step, never got past the first).
block{ x = {0, 40}, y = {0, 30} }
plot{ file = "tiny.pdf", show = { "blocks" }, axes = true, window = { 10, 10 + 1e-15, 10, 10 + 1e-15 } }
