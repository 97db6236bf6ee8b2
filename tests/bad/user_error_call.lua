-- line: 4
-- expect: error: stop here: the model has 1 blocks[^a-z]*$
block{ x = {0, 10}, y = {0, 10} }
error("stop here: the model has " .. info().blocks .. " blocks")
