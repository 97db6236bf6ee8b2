-- line: 4
-- expect: set: unknown key 'local' \(keys: mode, damping, local_damping, step, fraction, mixed, overlap\)
-- `local` is a Lua keyword: the coefficient is local_damping
set{ damping = "local", ["local"] = 0.5 }
