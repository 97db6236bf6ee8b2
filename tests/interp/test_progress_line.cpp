// The progress line: elapsed time, an estimate of the time left, and why the ratio jumped.
#include <gtest/gtest.h>

#include "cli_test.hpp"
#include "interp_test.hpp"
#include "progress_line.hpp"

namespace edem {
namespace {

using test::Cli;
using test::contains;
using test::Outcome;

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

TEST(ProgressLine, PrepassSaysItsStageLoadFactorAndIterations) {
  EXPECT_EQ(prepass_progress_line({.stage = "heading", .index = 2, .count = 17, .load = 0.6234, .iterations = 240,
                                   .seconds = 12.2}),
            "prepass: stage 2 of 17 (heading), load factor 0.623, 240 Newton iterations, 12 s run");
  EXPECT_EQ(prepass_progress_line({.stage = "present state", .index = 0, .count = 2, .load = 0.5, .iterations = 3}),
            "prepass: the present state, load factor 0.5, 3 Newton iterations, 0 s run");
}

// A prepass{} that runs longer than the progress interval reports as cycling does.
TEST_F(Cli, APrepassReportsItsProgress) {
  write("pre.lua", R"(block{ x = {-20, 20}, y = {-20, 20} }
jset{ angle = 60, spacing = 6, origin = {1, 0} }
region{ name = "hole", polygon = {{-3, -3}, {3, -3}, {3, 3}, {-3, 3}} }
zone{ edge = 0.5, far = 3, near = { "hole" } }
material{ "rock", model = "mohr", density = 2600, young = 5e9, poisson = 0.25, cohesion = 0.5e6, friction = 35,
          tension = 0.2e6 }
assign{ material = "rock" }
joint_material{ "joint", kn = 5e9, ks = 1e9, friction = 30 }
jassign{ material = "joint" }
insitu{ sxx = -4e6, syy = -5e6 }
boundary{ side = "left", fix = "x" }
boundary{ side = "right", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "top", fix = "y" }
prepass{ stages = { "hole" } }
)");
  const Outcome r = edem("--threads 1 --progress 0.001 run pre.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "prepass: stage 1 of 1 (hole), load factor ")) << r.out;
  EXPECT_TRUE(contains(r.out, " Newton iterations, ")) << r.out;
}

}  // namespace
}  // namespace edem
