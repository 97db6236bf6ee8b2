#include "solver/thread_watch.hpp"

#include <fmt/format.h>

namespace edem {

namespace {

constexpr double kWindow = 0.1;     // cycling time of one measurement [s]
// A balanced team waits for a fifth of its time or so (uneven chunks, the serial steps); a team
// one of whose threads is descheduled waits for half of it and more.
constexpr double kWaitShare = 0.4;
constexpr double kRetry = 10.0;     // cycling time between trials that failed or may now succeed [s]
// A smaller team is kept unless it is clearly slower (it takes less of a busy machine's time); a
// larger one is taken back when clearly faster.
constexpr double kSmallerKept = 0.95;
constexpr double kLargerTaken = 1.05;

}  // namespace

TeamChange watch_team(ThreadWatch& w, int team, double wall, double waited, long cycles, int wanted) {
  TeamChange out;
  if (team != w.team) {  // a new team (a trial, a changed model): a new window
    w.team = team;
    w.wall = w.waited = 0.0;
    w.cycles = 0;
  }
  w.wall += wall;
  w.waited += waited;
  w.cycles += cycles;
  if (w.wall < kWindow) return out;
  const double rate = static_cast<double>(w.cycles) / w.wall;
  const double share = w.waited / (static_cast<double>(team) * w.wall);
  const double window = w.wall;
  w.wall = w.waited = 0.0;
  w.cycles = 0;

  if (w.trying) {
    w.trying = false;
    const bool smaller = team < w.from_team;
    const bool better = rate > w.from_rate * (smaller ? kSmallerKept : kLargerTaken);
    if (!better) {
      w.cap = w.from_cap;
      out.changed = true;
      (smaller ? w.hold_down : w.hold_up) = kRetry;
    } else if (smaller) {
      w.hold_down = 0.0;  // fewer still may be faster
      w.hold_up = kRetry;
      if (!w.said) {
        w.said = true;
        out.notice = fmt::format(
            "the {} threads waited for each other {:.0f} % of the time (another process is busy on these "
            "cores, or there are more threads than cores); cycling goes on with {} thread{}, at {:.1f} times "
            "their speed; {} are tried again every {:.0f} s of cycling",
            w.from_team, 100.0 * w.from_share, team, team == 1 ? "" : "s", rate / w.from_rate, w.from_team, kRetry);
      }
    } else {
      if (w.cap >= wanted) w.cap = 0;
      w.hold_down = 0.0;
      w.hold_up = 0.0;  // the load went away: more may be faster still
    }
    return out;
  }

  w.hold_down -= window;
  w.hold_up -= window;
  const bool not_all_running = team >= 2 && share > kWaitShare;
  if (not_all_running && w.hold_down <= 0.0) {
    w.from_cap = w.cap;
    w.cap = team - 1;
  } else if (w.cap > 0 && w.hold_up <= 0.0) {
    w.from_cap = w.cap;
    w.cap = team + 1 >= wanted ? 0 : team + 1;
  } else {
    return out;
  }
  w.trying = true;
  w.from_team = team;
  w.from_rate = rate;
  w.from_share = share;
  out.changed = true;
  return out;
}

}  // namespace edem
