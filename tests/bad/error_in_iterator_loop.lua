-- line: 5
-- expect: lua: attempt to index a nil value \(field 'material'\)
block{ x = {0, 10}, y = {0, 10} }
for b in blocks() do
  print(b.material.name)
end
