-- line: 3
-- expect: block: expects a table, like .*, got 5
block(5)
