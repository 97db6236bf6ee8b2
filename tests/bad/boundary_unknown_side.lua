-- line: 5
-- expect: boundary: side must be one of left, right, top, bottom, got "botom" \(did you mean .bottom.\?\)
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
boundary{ side = "botom", fix = "y" }
