-- line: 3
-- expect: set: mode must be one of static, dynamic, got "quasistatic"
set{ mode = "quasistatic" }
