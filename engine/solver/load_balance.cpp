#include "solver/load_balance.hpp"

#include <algorithm>
#include <cmath>

namespace edem {

std::vector<double> even_cuts(int ranges) {
  std::vector<double> cuts(static_cast<size_t>(ranges) + 1);
  for (int t = 0; t <= ranges; ++t) cuts[static_cast<size_t>(t)] = static_cast<double>(t) / ranges;
  return cuts;
}

std::vector<int> split_at(const std::vector<double>& cuts, int items) {
  const long chunks = (items + kSplitChunk - 1) / kSplitChunk;
  std::vector<int> begin(cuts.size());
  for (size_t t = 0; t < cuts.size(); ++t) {
    const long chunk = std::lround(cuts[t] * static_cast<double>(chunks));
    begin[t] = static_cast<int>(std::clamp(chunk * kSplitChunk, 0L, static_cast<long>(items)));
  }
  begin.front() = 0;
  begin.back() = items;
  for (size_t t = 1; t < begin.size(); ++t) begin[t] = std::max(begin[t], begin[t - 1]);
  return begin;
}

void rebalance(std::vector<double>& cuts, const std::vector<double>& busy) {
  for (size_t t = 1; t + 1 < cuts.size(); ++t) {
    const double before = busy[t - 1], after = busy[t];
    const double span = cuts[t + 1] - cuts[t - 1];
    if (!(before + after > 0.0) || !(span > 0.0)) continue;
    const double move = 0.5 * 0.5 * (after - before) / (before + after) * span;
    cuts[t] = std::clamp(cuts[t] + move, cuts[t - 1], cuts[t + 1]);
  }
}

}  // namespace edem
