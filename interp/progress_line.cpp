#include "progress_line.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace edem {
namespace {

// ", about T left": for cycle() from the cycles left at the mean rate; for solve{} from how fast
// the ratio's logarithm fell since the last report, at most the cycles left. "" when it cannot
// tell (the first report, a ratio not falling).
std::string time_left(const RunProgress& last, const RunProgress& now, double rate) {
  if (!(rate > 0.0)) return "";
  const double by_cycles = static_cast<double>(now.max_cycles - now.run_cycles) / rate;
  if (now.target <= 0.0) return fmt::format(", about {} left", clock_time(by_cycles));
  if (last.seconds <= 0.0 || !(now.ratio > 0.0) || !(last.ratio > now.ratio) || now.ratio <= now.target) return "";
  const double falling = std::log(last.ratio / now.ratio) / (now.seconds - last.seconds);  // per second
  return fmt::format(", about {} left", clock_time(std::min(by_cycles, std::log(now.ratio / now.target) / falling)));
}

// What changed with a ratio that jumped tenfold or more since the last report: new cracks, more
// contacts slipping or open, a release running.
std::string ratio_jump(const RunProgress& last, const RunProgress& now) {
  if (last.seconds <= 0.0 || !(now.ratio >= 10.0 * last.ratio)) return "";
  std::vector<std::string> what;
  if (now.cracks > last.cracks) what.push_back(fmt::format("{} new cracks", now.cracks - last.cracks));
  if (now.slipping > last.slipping) what.push_back(fmt::format("{} more contacts slipping", now.slipping - last.slipping));
  if (now.open > last.open) what.push_back(fmt::format("{} more contacts open", now.open - last.open));
  if (now.releasing > 0) what.push_back("an excavation's load coming off");
  if (what.empty()) what.push_back("no crack, slip or opening: the model is moving");
  return fmt::format("; ratio up {:.0f} times since the last line: {}", now.ratio / last.ratio, fmt::join(what, ", "));
}

}  // namespace

std::string clock_time(double seconds) {
  const long s = std::lround(seconds);
  if (s < 60) return fmt::format("{} s", s);
  if (s < 3600) return fmt::format("{} min {:02} s", s / 60, s % 60);
  return fmt::format("{} h {:02} min", s / 3600, (s % 3600) / 60);
}

std::string progress_line(const RunProgress& last, const RunProgress& now) {
  const double rate = now.seconds > 0.0 ? static_cast<double>(now.run_cycles) / now.seconds : 0.0;
  return fmt::format("cycle {} ({} of {}), ratio {:.3g}{}, cracks {}, stage {}, {:.0f} cycles/s, {} run{}{}", now.cycle,
                     now.run_cycles, now.max_cycles, now.ratio,
                     now.target > 0.0 ? fmt::format(" (to {:.3g})", now.target) : "", now.cracks, now.stage, rate,
                     clock_time(now.seconds), time_left(last, now, rate), ratio_jump(last, now));
}

std::string prepass_progress_line(const PrepassProgress& p) {
  const std::string stage = p.index == 0 ? "the present state" : fmt::format("stage {} of {} ({})", p.index, p.count, p.stage);
  return fmt::format("prepass: {}, load factor {:.3g}, {} Newton iterations, {} run", stage, p.load, p.iterations,
                     clock_time(p.seconds));
}

}  // namespace edem
