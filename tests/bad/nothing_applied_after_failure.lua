-- line: 9
-- expect: error: 1 joint set after a failed jset
-- A failed command changes nothing: the second jset is rejected whole.
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 0, spacing = 2 }
local ok = pcall(jset, { angle = 45, spacing = 1, gap = -1 })
assert(not ok, "the bad jset must fail")
assert(info().joint_sets == 1)
error(info().joint_sets .. " joint set after a failed jset")
