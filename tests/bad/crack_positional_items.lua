-- line: 4
-- expect: crack: unexpected positional item #1 \(a table\): crack takes only named keys
block{ x = {0, 10}, y = {0, 10} }
crack{ {1, 1}, {5, 5} }
