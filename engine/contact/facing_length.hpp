// The length a gridpoint's own edges give its contact with an edge of another block, as a function
// of where the nodes are: of each half-edge that faces the edge (one of a corner's two contacts
// in a corner counts only the half-edge along its own face), its projection on the edge's line
// (clipped at an end that is a convex corner of the edge's block: past it the half-edge is beside
// the block; for one of such two also where its face meets the other's) times how squarely it
// faces the edge, and half of that, the other half being the other side's (contacts.hpp). It is
// what a detection finds over a face (detect.cpp, give_half_edges, which also shares a half-edge
// between the faces of two blocks, and past a blunt corner counts the piece over the next face),
// and it changes at first order both as the blocks turn against each other (at an oblique corner)
// and as a gridpoint slides past a corner; its slope with respect to the nodes lets a contact's
// force pay for what that change does to its energy (contact_force.hpp).
#pragma once

#include <cmath>

namespace edem {

// Where the nodes are [m]: the gridpoint, the far ends of its edges before and after it along its
// loop, and the edge's ends a and b; whether the projection stops at a (b); whether the half-edge
// towards far_a (far_b) counts.
struct FacingNodes {
  double p[2], far_a[2], far_b[2], a[2], b[2];
  bool clip_a = false, clip_b = false;
  bool count_a = true, count_b = true;
};

// The slope of the facing length with respect to each node's position [-].
struct FacingSlope {
  double p[2] = {}, far_a[2] = {}, far_b[2] = {}, a[2] = {}, b[2] = {};
};

// The facing length [m]; with `slope`, its slope too.
inline double facing_length(const FacingNodes& g, FacingSlope* slope) {
  const double ex = g.b[0] - g.a[0], ey = g.b[1] - g.a[1];
  const double len = std::sqrt(ex * ex + ey * ey);
  const double sx = ex / len, sy = ey / len;
  double total = 0.0, by_s[2] = {0.0, 0.0};
  for (int i = 0; i < 2; ++i) {
    if (!(i == 0 ? g.count_a : g.count_b)) continue;
    const double* f = i == 0 ? g.far_a : g.far_b;
    const double sign = i == 0 ? 1.0 : -1.0;  // the edge in its loop's direction: sign (p - f)
    const double dx = sign * (g.p[0] - f[0]), dy = sign * (g.p[1] - f[1]);
    const double along = dx * sx + dy * sy;
    if (!(along < 0.0)) continue;  // runs with the edge, not against it: does not face it
    const double size = std::sqrt(dx * dx + dy * dy);
    const double squarely = -along / size;
    // The half-edge from p to its middle q, projected on the edge's line, measured from a.
    const double qx = 0.5 * (g.p[0] + f[0]), qy = 0.5 * (g.p[1] + f[1]);
    const double up = (g.p[0] - g.a[0]) * sx + (g.p[1] - g.a[1]) * sy;
    const double uq = (qx - g.a[0]) * sx + (qy - g.a[1]) * sy;
    // Which of p (0), q (1) or the clip (2) bounds it below and above.
    int low_by = up < uq ? 0 : 1, high_by = 1 - low_by;
    double low = std::min(up, uq), high = std::max(up, uq);
    if (g.clip_a && low < 0.0) low = 0.0, low_by = 2;
    if (g.clip_b && high > len) high = len, high_by = 2;
    if (!(high > low)) continue;
    const double cover = high - low;
    total += 0.5 * squarely * cover;
    if (!slope) continue;
    const double by_up = (high_by == 0) - (low_by == 0), by_uq = (high_by == 1) - (low_by == 1);
    const double by_len = high_by == 2 ? 1.0 : 0.0;
    // How squarely it faces, with respect to d and to s (a free vector).
    const double sq_d[2] = {-sx / size + along * dx / (size * size * size),
                            -sy / size + along * dy / (size * size * size)};
    const double sq_s[2] = {-dx / size, -dy / size};
    double* fs = i == 0 ? slope->far_a : slope->far_b;
    for (int k = 0; k < 2; ++k) {
      const double s = k == 0 ? sx : sy;
      const double pk = g.p[k] - g.a[k], qk = (k == 0 ? qx : qy) - g.a[k];
      slope->p[k] += 0.5 * (squarely * (by_up + 0.5 * by_uq) * s + cover * sign * sq_d[k]);
      fs[k] += 0.5 * (squarely * 0.5 * by_uq * s - cover * sign * sq_d[k]);
      by_s[k] += 0.5 * (squarely * (by_up * pk + by_uq * qk) + cover * sq_s[k]);
      slope->a[k] += -0.5 * squarely * (by_up + by_uq + by_len) * s;
      slope->b[k] += 0.5 * squarely * by_len * s;
    }
  }
  if (slope) {  // s = (b - a) / |b - a|: only its part across s turns it
    const double across = by_s[0] * sx + by_s[1] * sy;
    const double by_e[2] = {(by_s[0] - across * sx) / len, (by_s[1] - across * sy) / len};
    for (int k = 0; k < 2; ++k) {
      slope->a[k] -= by_e[k];
      slope->b[k] += by_e[k];
    }
  }
  return total;
}

}  // namespace edem
