-- line: 6
-- expect: crackseed: cannot resolve geometry features smaller than the tolerance \(0\.[0-9]+ m\) in block 1: near \([-0-9.e]+, [-0-9.e]+\) cuts of (joint set 1 and crackseed 1|crackseed 1 and joint set 1) keep coming closer than that
model{ tolerance = 1e-3 }
block{ x = {-100, 100}, y = {-90, 90} }
jset{ angle = 60, spacing = {16, 12, 8} }
crackseed{ angles = {60.5, 119.5}, spacing = 4.8, origin = {1.3, 0.7} }
