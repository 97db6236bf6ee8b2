-- line: 7
-- expect: jset: these cuts would make about 2.25e\+05 blocks, more than max_blocks = 1e\+05
-- Joint sets that would cut a long block into a quarter of a million blocks are refused before
-- any cutting (cutting and zoning them took minutes), naming the estimate and the limit.
block{ x = {0, 48}, y = {0, 100000} }
jset{ angle = 0, spacing = 4 }
jset{ angle = 90, spacing = 6 }
