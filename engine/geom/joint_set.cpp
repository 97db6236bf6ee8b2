#include "geom/joint_set.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "core/error.hpp"

namespace edem {
namespace {

// Uniform in [-1, 1) from a 64-bit Mersenne Twister, the same on every platform
// (std::uniform_real_distribution is not specified bit-for-bit).
class Deviation {
 public:
  explicit Deviation(std::uint64_t seed) : engine_(seed) {}
  double operator()(double amplitude) {
    if (amplitude == 0.0) return 0.0;
    const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;  // [0, 1)
    return amplitude * (2.0 * unit - 1.0);
  }

 private:
  std::mt19937_64 engine_;
};

constexpr double kMaxTraces = 2e6;

}  // namespace

std::vector<CutSegment> joint_set_traces(const JointSetDef& def, const Box& extent, int set,
                                         int clip) {
  const double radians = def.angle * std::numbers::pi / 180.0;
  const Vec2 along{std::cos(radians), std::sin(radians)};
  const Vec2 across{-along.y, along.x};

  // Extent of the box in the joint's frame (origin at def.origin), with a margin so that
  // traces tilted by angle_dev still reach the corners.
  double s0 = INFINITY, s1 = -INFINITY, t0 = INFINITY, t1 = -INFINITY;
  for (Vec2 corner : {Vec2{extent.x0, extent.y0}, Vec2{extent.x1, extent.y0},
                      Vec2{extent.x0, extent.y1}, Vec2{extent.x1, extent.y1}}) {
    const Vec2 d = corner - def.origin;
    s0 = std::min(s0, dot(d, across));
    s1 = std::max(s1, dot(d, across));
    t0 = std::min(t0, dot(d, along));
    t1 = std::max(t1, dot(d, along));
  }
  const double margin = 0.1 * extent.diagonal();
  t0 -= margin;
  t1 += margin;

  double min_spacing = INFINITY;
  for (double s : def.spacing) min_spacing = std::min(min_spacing, s);
  const double lines = (s1 - s0) / (min_spacing - def.spacing_dev);
  const double traces_per_line =
      std::isfinite(def.trace) ? (t1 - t0) / (def.trace - def.trace_dev + def.gap) : 1.0;
  if (lines * traces_per_line > kMaxTraces)
    fail("joint set would make about {:.3g} traces; spacing or trace is too small for a model "
         "of this size",
         lines * traces_per_line);

  Deviation deviation(def.seed);
  // Offsets of the lines across the set: the spacing list in turn going up from the origin,
  // and backwards going down, so the pattern is periodic with period sum(spacing). Only those
  // across the model are kept: an origin far from it costs steps, not memory.
  std::vector<double> offsets;
  const size_t n = def.spacing.size();
  const auto keep = [&](double offset) {
    if (offset >= s0 && offset <= s1) offsets.push_back(offset);
  };
  double above = 0.0;
  keep(above);
  for (size_t i = 0; above <= s1; ++i) {
    above += def.spacing[i % n] + deviation(def.spacing_dev);
    keep(above);
  }
  double below = 0.0;
  for (size_t i = 0; below >= s0; ++i) {
    below -= def.spacing[n - 1 - i % n] + deviation(def.spacing_dev);
    keep(below);
  }

  std::vector<CutSegment> traces;
  const EdgeOrigin origin{EdgeKind::joint, set, set, false};
  for (double offset : offsets) {
    const Vec2 base = def.origin + offset * across;
    auto add_trace = [&](double from, double to) {
      Vec2 a = base + from * along, b = base + to * along;
      if (def.angle_dev > 0.0) {
        const double turn = deviation(def.angle_dev) * std::numbers::pi / 180.0;
        const Vec2 mid = 0.5 * (a + b), half = 0.5 * (b - a);
        const Vec2 rotated{half.x * std::cos(turn) - half.y * std::sin(turn),
                           half.x * std::sin(turn) + half.y * std::cos(turn)};
        a = mid - rotated;
        b = mid + rotated;
      }
      traces.push_back({a, b, origin, clip});
    };
    if (!std::isfinite(def.trace)) {
      add_trace(t0, t1);
      continue;
    }
    // Traces start at the origin's foot on this line and repeat both ways: trace, gap, ...
    for (double t = 0.0; t < t1;) {
      const double length = def.trace + deviation(def.trace_dev);
      add_trace(t, t + length);
      t += length + def.gap + deviation(def.gap_dev);
    }
    for (double t = 0.0; t > t0;) {
      const double gap = def.gap + deviation(def.gap_dev);
      const double length = def.trace + deviation(def.trace_dev);
      add_trace(t - gap - length, t - gap);
      t -= gap + length;
    }
  }
  return traces;
}

}  // namespace edem
