-- line: 3
-- expect: cancel: no callback with handle 42
cancel(42)
