-- line: 3
-- expect: block: x must be \{x0, x1\} with x0 < x1, got \{5, 5\}
block{ x = {5, 5}, y = {0, 10} }
