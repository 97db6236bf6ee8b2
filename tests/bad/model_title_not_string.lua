-- line: 3
-- expect: model: title must be a string, got 42
model{ title = 42 }
