-- A script that builds a table without end: Lua's own out-of-memory error carries no position,
-- and edem names the line it ran out near (tests/fuzz/out_of_memory.sh runs it under a memory
-- limit).
local function outline(width, height, segments)
  local points = {}
  for i = 0, segments do
    points[#points + 1] = { width * math.cos(i), height * math.sin(i) }
  end
  return points
end
outline(8, 4, 9007199254740993)
