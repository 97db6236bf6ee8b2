-- line: 3
-- expect: history: item #1 \(quantity\) must be one of ratio, .*, got "disp"
history{ "disp", at = {0, 0} }
