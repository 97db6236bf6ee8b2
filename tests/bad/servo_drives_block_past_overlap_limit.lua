-- line: 20
-- expect: cycle: cycle [0-9]+: overlap too great: the gridpoint at \([-0-9.e]+, [-0-9.e]+\) of block [0-9]+ is [0-9.e-]+ m inside block [0-9]+, more than the limit of 0.125 m
-- A stiff block driven down 0.1 mm a cycle through a soft joint into the block below, its
-- velocity given again before every cycle, as a servo would. Each boundary{} has the contacts
-- found again before the cycle runs: a contact already past the watchdog's limit (half the median
-- edge, 0.125 m) must still be found, so that the run stops there and says why, instead of the
-- block sinking on through the one below with no contact at all.
model{ title = "a block driven into another" }
block{ x = {0, 3}, y = {-1, 0} }
block{ x = {1, 2}, y = {0, 1} }
zone{ edge = 0.5 }
material{ "rock", density = 2600, young = 1e12, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "soft", kn = 1e7, ks = 1e7, friction = 30 }
jassign{ material = "soft" }
boundary{ polygon = {{-0.1, -1.1}, {3.1, -1.1}, {3.1, -0.9}, {-0.1, -0.9}}, fix = "xy" }
-- 2,000 cycles would drive it 0.2 m in.
for _ = 1, 2000 do
  boundary{ polygon = {{0.9, 0.9}, {2.1, 0.9}, {2.1, 1.1}, {0.9, 1.1}}, yvel = -1e-4 }
  cycle(1)
end
