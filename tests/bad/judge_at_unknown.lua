-- line: 3
-- expect: judge: at must be one of cycles, equilibrium, got "equilibrum" \(did you mean .equilibrium.\?\)
judge{ at = "equilibrum" }
