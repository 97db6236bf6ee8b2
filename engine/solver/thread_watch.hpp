// Threads that degrade gracefully: each batch of cycles reports its wall time and its threads'
// waits at the barriers; when the team waits far more than a balanced one does, a team of one
// thread fewer is tried, and kept while it is faster; a larger team is tried again now and then.
// The results do not depend on the team size, only the speed does.
#pragma once

#include <string>

#include "state/thread_watch.hpp"

namespace edem {

struct TeamChange {
  bool changed = false;  // the cap changed: the work is to be split again
  std::string notice;    // said once, when a run first takes fewer threads
};

// Takes a batch's figures (`team` threads, `wall` seconds, `waited` seconds of waits summed over
// the team, `cycles`) for a run that would use `wanted` threads unwatched.
TeamChange watch_team(ThreadWatch& watch, int team, double wall, double waited, long cycles, int wanted);

}  // namespace edem
