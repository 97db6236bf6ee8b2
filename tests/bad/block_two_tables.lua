-- line: 3
-- expect: block: expects one table, like .*, got 2 arguments
block({ x = {0, 10}, y = {0, 10} }, { x = {10, 20}, y = {0, 10} })
