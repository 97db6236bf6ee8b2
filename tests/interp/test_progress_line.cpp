// The progress line: elapsed time, an estimate of the time left, and why the ratio jumped.
#include <gtest/gtest.h>

#include "interp_test.hpp"
#include "progress_line.hpp"

namespace edem {
namespace {

using test::contains;

TEST(ProgressLine, SaysHowLongTheRunHasRunAndHasLeft) {
  EXPECT_EQ(clock_time(42.4), "42 s");
  EXPECT_EQ(clock_time(185), "3 min 05 s");
  EXPECT_EQ(clock_time(7620), "2 h 07 min");
  // cycle(): the cycles left at the mean rate (1000 cycles/s, 9000 to go).
  const RunProgress cycling{.cycle = 1000, .run_cycles = 1000, .max_cycles = 10000, .seconds = 1.0};
  EXPECT_EQ(progress_line({}, cycling),
            "cycle 1000 (1000 of 10000), ratio 0, cracks 0, stage 0, 1000 cycles/s, 1 s run, about 9 s left");
  // solve{}: the ratio fell tenfold in 10 s and has a thousandfold to go: about 30 s more.
  const RunProgress before{.cycle = 1000, .run_cycles = 1000, .max_cycles = 1000000, .ratio = 1e-4, .target = 1e-8,
                           .seconds = 10.0};
  RunProgress after = before;
  after.cycle = after.run_cycles = 2000, after.ratio = 1e-5, after.seconds = 20.0;
  EXPECT_TRUE(contains(progress_line(before, after), "ratio 1e-05 (to 1e-08), cracks 0, stage 0, 100 cycles/s, "
                                                      "20 s run, about 30 s left"));
  // The first report of a solve, or a ratio that is not falling, makes no estimate.
  EXPECT_FALSE(contains(progress_line({}, before), "left"));
  EXPECT_FALSE(contains(progress_line(after, before), "left"));
}

TEST(ProgressLine, SaysWhatChangedWhenTheRatioJumps) {
  const RunProgress before{.cycle = 1000, .run_cycles = 1000, .max_cycles = 100000, .ratio = 1e-7, .target = 1e-6,
                           .cracks = 4, .seconds = 10.0, .slipping = 2, .open = 1};
  RunProgress after = before;
  after.ratio = 3e-4, after.seconds = 11.0, after.cracks = 7, after.slipping = 14;
  EXPECT_TRUE(contains(progress_line(before, after),
                       "; ratio up 3000 times since the last line: 3 new cracks, 12 more contacts slipping"));
  after.cracks = 4, after.slipping = 2, after.releasing = 300;
  EXPECT_TRUE(contains(progress_line(before, after), "an excavation's load coming off"));
  after.releasing = 0;
  EXPECT_TRUE(contains(progress_line(before, after), "no crack, slip or opening: the model is moving"));
  after.ratio = 5e-7;  // fivefold: not a jump
  EXPECT_FALSE(contains(progress_line(before, after), "ratio up"));
}

}  // namespace
}  // namespace edem
