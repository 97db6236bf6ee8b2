// The force of one contact over one step: geometry from the current positions, the normal
// stress from the closure (joint_law.hpp), the shear force incrementally, then Coulomb slip,
// dilation and the loss of cohesion and tension once it slips or opens.
#pragma once

#include <algorithm>
#include <cmath>

#include "contact/contacts.hpp"
#include "contact/joint_law.hpp"

namespace edem {

// Updates `c` and its force on the gridpoint (c.fx, c.fy) from the node positions, origin + u,
// and velocities `v`; returns the overlap, how far the
// gridpoint is inside the edge's block [m] (negative: a gap).
[[gnu::always_inline]] inline double contact_force(Contact& c, const ContactEdge& e, const JointParams& p,
                                                   const double* origin, const double* u,
                                                   const double* v, double dt) {
  const size_t n = static_cast<size_t>(c.node), a = static_cast<size_t>(e.a), b = static_cast<size_t>(e.b);
  const auto x = [&](size_t dof) { return origin[dof] + u[dof]; };
  const double xa = x(2 * a), ya = x(2 * a + 1);
  const double dx = x(2 * b) - xa, dy = x(2 * b + 1) - ya;
  const double px = x(2 * n) - xa, py = x(2 * n + 1) - ya;
  const double len = std::sqrt(dx * dx + dy * dy);
  const double sx = dx / len, sy = dy / len;  // along the edge
  const double nx = sy, ny = -sx;             // out of the edge's block
  const double t_line = (px * sx + py * sy) / len;
  const double t = std::clamp(t_line, 0.0, 1.0);
  double gap = (px - t * dx) * nx + (py - t * dy) * ny;
  // Past the end of the edge at a convex corner of its block, the gridpoint is in contact only if
  // it is behind the corner's other edge too: the gap is the larger of the two (a gridpoint next
  // to a pressed-in corner is beside it, not under it). Where the boundary goes on straight, the
  // gridpoint is over the next edge and the gap stays as it is.
  const int beyond = t_line < 0.0 ? e.beyond_a : t_line > 1.0 ? e.beyond_b : -1;
  if (beyond >= 0) {
    const size_t f = static_cast<size_t>(beyond);
    // The corner's other edge, from the corner to `beyond` (t = 1) or from `beyond` to it (t = 0).
    const double cx = t * dx, cy = t * dy;
    const double ox = x(2 * f) - xa - cx, oy = x(2 * f + 1) - ya - cy;
    const double olen = std::sqrt(ox * ox + oy * oy);
    const double sign = t > 0.5 ? 1.0 : -1.0;  // keep the block on the left of the direction
    const double onx = sign * oy / olen, ony = -sign * ox / olen;
    gap = std::max(gap, (px - cx) * onx + (py - cy) * ony);
  }
  const double rvx = v[2 * n] - ((1.0 - t) * v[2 * a] + t * v[2 * b]);
  const double rvy = v[2 * n + 1] - ((1.0 - t) * v[2 * a + 1] + t * v[2 * b + 1]);
  const double dus = (rvx * sx + rvy * sy) * dt;
  c.t = t;
  c.us += dus;
  c.closure = c.closure0 - gap - c.dilation;

  double sn = normal_stress(p, c.closure);
  bool open = false;
  if (c.intact) {
    if (sn < -p.tension) {  // fails in tension: the bond is gone
      c.intact = false;
      open = true;
    }
  } else if (c.closure <= 0.0) {
    open = true;
  }
  if (open) {
    c.sn = 0.0;
    c.fs = 0.0;
    c.state = ContactState::open;
    c.fx = c.fy = 0.0;
    return -gap;
  }
  const double ks = p.ks * c.length;
  const double trial = c.fs - ks * dus;
  const double limit = std::max(0.0, ((c.intact ? p.cohesion : 0.0) + p.tan_friction * sn) * c.length);
  if (std::fabs(trial) > limit) {
    const double plastic = (std::fabs(trial) - limit) / ks;
    c.fs = std::copysign(limit, trial);
    c.slip += plastic;
    if (sn > 0.0) c.dilation += p.tan_dilation * plastic;
    c.intact = false;
    c.state = ContactState::slip;
  } else {
    c.fs = trial;
    c.state = c.intact ? ContactState::bonded : ContactState::elastic;
  }
  c.sn = sn;
  const double fn = sn * c.length;
  c.fx = fn * nx + c.fs * sx;
  c.fy = fn * ny + c.fs * sy;
  return -gap;
}

}  // namespace edem
