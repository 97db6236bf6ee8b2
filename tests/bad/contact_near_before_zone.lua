-- line: 4
-- expect: contact_near: the model has no zones: zone\{\.\.\.\} the blocks first
block{ x = {0, 10}, y = {0, 10} }
local c = contact_near(5, 5)
