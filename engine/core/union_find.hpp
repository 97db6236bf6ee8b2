// Union-find over indices 0..n-1: parent[i] == i at a root.
#pragma once

#include <vector>

namespace edem {

// The root of i's group, halving the path on the way.
inline int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<size_t>(i)] != i) {
    parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
    i = parent[static_cast<size_t>(i)];
  }
  return i;
}

}  // namespace edem
