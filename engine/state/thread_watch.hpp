// What a run knows about how its threads are doing (runtime state, not saved): a team whose
// threads are not all running, because another process holds a core or more threads were asked
// for than there are cores, waits at every barrier for a thread the kernel has descheduled and
// can run many times slower than one thread. solver/thread_watch.cpp measures the waits and
// shrinks the team while a smaller one is faster.
#pragma once

namespace edem {

struct ThreadWatch {
  int cap = 0;  // at most this many threads (0: no limit)
  // The window being measured: its team size, cycling time [s], barrier waits summed over the
  // team [s], and cycles.
  int team = 0;
  double wall = 0.0, waited = 0.0;
  long cycles = 0;
  // A trial of another team size: the team, cap and rate [cycles/s] it is measured against.
  bool trying = false;
  int from_team = 0, from_cap = 0;
  double from_rate = 0.0, from_share = 0.0;
  // Cycling time [s] to wait before trying a smaller or a larger team again.
  double hold_down = 0.0, hold_up = 0.0;
  bool said = false;  // the run has said that it took fewer threads
};

}  // namespace edem
