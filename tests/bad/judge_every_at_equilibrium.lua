-- line: 3
-- expect: judge: every is for at = "cycles" \(a judgment every n cycles\); at = "equilibrium" judges each state a solve\{\} brings to its ratio
judge{ at = "equilibrium", every = 10 }
