-- line: 5
-- expect: jset: spacing must be > 0, got -1.*traceback:.*:5: in function 'cut'.*:9: in function 'cut_all'.*:13: in main chunk
block{ x = {0, 10}, y = {0, 10} }
local function cut(angle, spacing)
  return jset{ angle = angle, spacing = spacing }
end

local function cut_all(sets)
  for _, s in ipairs(sets) do cut(s[1], s[2]) end
end

-- the second set has a negative spacing
cut_all({ {30, 1}, {-60, -1} })
