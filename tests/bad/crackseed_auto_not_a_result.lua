-- line: 4
-- expect: crackseed: auto must be a prepass\{\} result: it has no zones list
block{ x = {0, 10}, y = {0, 10} }
crackseed{ auto = { seconds = 1 } }
