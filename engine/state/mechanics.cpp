#include "state/mechanics.hpp"

#include <omp.h>

#include <algorithm>

namespace edem {

namespace {

// Threads as asked (all the machine's by default), but no more than the model can keep busy:
// each cycle ends in two barriers, and a thread with less than this much work (zones and
// boundary gridpoints that may touch) waits more than it works; on a loaded machine a barrier
// can cost a scheduler time slice, and a model of a few hundred zones then runs many times
// slower on two threads than on one. Results do not depend on the thread count.
constexpr size_t kWorkPerThread = 1000;

}  // namespace

int asked_threads(const Mechanics& m) {
  // OpenMP's default is the cores the process may run on (its affinity mask), or OMP_NUM_THREADS.
  return m.threads > 0 ? m.threads : std::max(1, omp_get_max_threads());
}

int wanted_threads(const Mechanics& m) {
  const int wanted = asked_threads(m);
  const size_t work = m.active.size() + (m.faces.touchable_blocks > 1 ? m.faces.nodes.size() : 0);
  return static_cast<int>(std::clamp<size_t>(work / kWorkPerThread, 1, static_cast<size_t>(wanted)));
}

int thread_count(const Mechanics& m) {
  const int wanted = wanted_threads(m);
  return m.thread_watch.cap > 0 ? std::min(wanted, m.thread_watch.cap) : wanted;
}

}  // namespace edem
