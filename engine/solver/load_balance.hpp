// Where the contacts and the nodes are split among threads. A contact's cost differs with its
// kind (a face's length that follows its facing half-edges, a tip short of a corner), and the
// first thread also releases an excavation's loads and moves the bolts, so an even split by
// count leaves one thread waiting for the other at every cycle's barriers. Each split point is
// moved towards equal times as the threads measure them. Where the points fall changes no
// result: each contact and node writes only its own entries and its block's sums, added in
// block order (cycle.cpp).
#pragma once

#include <vector>

namespace edem {

// Contacts and nodes are split at multiples of this many; their partial sums are taken over
// the same blocks.
inline constexpr int kSplitChunk = 64;

// The share of the items [0, 1] before each of `ranges` ranges, and the last's end: even.
std::vector<double> even_cuts(int ranges);

// The first item of each range (and the end) for `items` items at `cuts`, at multiples of
// kSplitChunk.
std::vector<int> split_at(const std::vector<double>& cuts, int items);

// Moves each inner cut towards equal times of the ranges on either side, given the seconds
// each range took (`busy`): by half of what equal times would need, were the cost spread
// evenly over the two ranges' items (the half damps the measurement's noise).
void rebalance(std::vector<double>& cuts, const std::vector<double>& busy);

}  // namespace edem
