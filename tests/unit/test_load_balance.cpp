// Where contacts and nodes are split among threads: at multiples of the split chunk, covering
// every item once, and moved by the measured times until the threads take as long as each other.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver/load_balance.hpp"

namespace edem {
namespace {

// Seconds each range takes at `begin`: items cost `cheap` each before `dear_from`, `dear` after,
// and the first range also does `serial` seconds of its own.
std::vector<double> times(const std::vector<int>& begin, int dear_from, double cheap, double dear,
                          double serial) {
  std::vector<double> busy(begin.size() - 1, 0.0);
  for (size_t r = 0; r + 1 < begin.size(); ++r)
    for (int i = begin[r]; i < begin[r + 1]; ++i) busy[r] += i < dear_from ? cheap : dear;
  busy[0] += serial;
  return busy;
}

TEST(LoadBalance, RangesStartAtMultiplesOfTheChunkAndCoverEveryItemOnce) {
  for (const int items : {0, 1, 63, 64, 65, 1000, 8191}) {
    for (const int ranges : {1, 2, 3, 8}) {
      const std::vector<int> begin = split_at(even_cuts(ranges), items);
      ASSERT_EQ(begin.size(), static_cast<size_t>(ranges) + 1);
      EXPECT_EQ(begin.front(), 0);
      EXPECT_EQ(begin.back(), items);
      for (size_t t = 1; t < begin.size(); ++t) {
        EXPECT_LE(begin[t - 1], begin[t]);
        if (t + 1 < begin.size() && begin[t] < items) {
          EXPECT_EQ(begin[t] % kSplitChunk, 0) << items << " " << t;
        }
      }
    }
  }
}

TEST(LoadBalance, EvenTimesLeaveTheCutsWhereTheyAre) {
  std::vector<double> cuts = even_cuts(2);
  rebalance(cuts, {0.3, 0.3});
  EXPECT_EQ(cuts, even_cuts(2));
  rebalance(cuts, {0.0, 0.0});  // nothing measured: nothing to go by
  EXPECT_EQ(cuts, even_cuts(2));
}

// Half the items cost three times the others and the first thread has serial work of its own:
// the cuts move until the threads' times differ by no more than a chunk's cost.
TEST(LoadBalance, CutsMoveUntilTheThreadsTakeAsLongAsEachOther) {
  const int items = 8000;
  for (const int ranges : {2, 3, 4}) {
    std::vector<double> cuts = even_cuts(ranges);
    const double cheap = 1e-6, dear = 3e-6, serial = 5e-4;
    const std::vector<double> start = times(split_at(cuts, items), items / 2, cheap, dear, serial);
    double spread = 0.0;
    for (int batch = 0; batch < 200; ++batch)
      rebalance(cuts, times(split_at(cuts, items), items / 2, cheap, dear, serial));
    const std::vector<double> busy = times(split_at(cuts, items), items / 2, cheap, dear, serial);
    for (size_t r = 1; r < busy.size(); ++r) spread = std::max(spread, std::fabs(busy[r] - busy[0]));
    double start_spread = 0.0;
    for (size_t r = 1; r < start.size(); ++r) start_spread = std::max(start_spread, std::fabs(start[r] - start[0]));
    EXPECT_GT(start_spread, 10 * kSplitChunk * dear) << ranges;
    EXPECT_LE(spread, 2 * kSplitChunk * dear) << ranges;
  }
}

}  // namespace
}  // namespace edem
