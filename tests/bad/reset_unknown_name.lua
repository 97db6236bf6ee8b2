-- line: 3
-- expect: reset: item #2 must be one of displacement, velocity, state, joint, got "velocities" \(did you mean .velocity.\?\)
reset{ "displacement", "velocities" }
