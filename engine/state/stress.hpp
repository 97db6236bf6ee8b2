// A zone's stress in plane strain, compression negative.
#pragma once

namespace edem {

struct Stress {
  double xx = 0.0, yy = 0.0, xy = 0.0, zz = 0.0;  // [Pa]
};

inline double mean_stress(const Stress& s) { return (s.xx + s.yy + s.zz) * (1.0 / 3.0); }

}  // namespace edem
