// A gridpoint past an end of its contact's edge where the block's boundary bends (turns in, or out
// by less than a convex corner's angle: ContactEdge::bent_a, bent_b), and past the neighbouring
// edge's end as well, is nearest that vertex itself: beside a re-entrant corner it is inside the
// block by its distance to the vertex and pushed out towards it; beside a slight outward bend it
// is outside by that distance. Either edge at the vertex then gives the same gap and direction, as
// the distance to the block's boundary does. By each edge's own line the depth would hang on the
// face a detection picks: a corner pressed into a notch, its contact switched between the notch's
// two faces at each detection, would take energy from every switch.
#pragma once

#include <cmath>

namespace edem {

struct PastTheEnd {
  double nx = 0.0, ny = 0.0;  // out of the block, at the gridpoint
  double gap = 0.0;           // [m], negative inside
};

// q: the gridpoint less the vertex; o: the neighbouring edge's other end less the vertex; (sx, sy):
// the edge's direction, a to b; at_a: the vertex is the edge's end a. False where the gridpoint is
// over the neighbouring edge (or on the vertex): the edge's line holds there.
inline bool past_the_end(double qx, double qy, double ox, double oy, double sx, double sy, bool at_a,
                         PastTheEnd& out) {
  const double dist = std::sqrt(qx * qx + qy * qy);
  if (!(qx * ox + qy * oy < 0.0 && dist > 0.0)) return false;
  // Seen along the boundary (the block on its left), the turn at the vertex: left at a convex one.
  const double turn = at_a ? oy * sx - ox * sy : sx * oy - sy * ox;
  const double side = turn < 0.0 ? -1.0 : 1.0;
  // Past both ends of a re-entrant corner is inside the block, of a convex one outside: the other
  // side of the edge's line (along a straight run, by round-off) is over the edges, not past them.
  if (!(side * (qx * sy - qy * sx) > 0.0)) return false;
  out.nx = side * qx / dist;
  out.ny = side * qy / dist;
  out.gap = side * dist;
  return true;
}

}  // namespace edem
