-- line: 5
-- expect: zonee: unknown command \(did you mean 'zone'\?\).*traceback:.*in function 'mesh'.*in main chunk
block{ x = {0, 10}, y = {0, 10} }
local function mesh(size)
  zonee{ edge = size }
end
mesh(1)
