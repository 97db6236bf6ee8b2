// Which edge of another block a boundary gridpoint's contact goes to (detect.cpp). The edges
// offered are those about as near as the nearest; the one facing the gridpoint's own boundary
// most squarely wins (the most negative opposition, the dot product of the edge's outward normal
// with the sum of the gridpoint's own edges' outward normals), and among equals the nearest: a
// gridpoint at, or pressed a little into, the corner of the other block belongs to the face it
// lies against, not to the side edge that happens to be a micrometre nearer.
//
// The edge the contact had before (`held`) is kept while it is offered, and it faces the boundary
// within kHeldFacing of the best, or the best is an edge the gridpoint lies past the end of. Past
// the held edge's end itself, it is left for a best the gridpoint projects onto (sliding along a
// face, it goes on to the next edge), and kept otherwise while its contact presses: beyond a convex
// corner of the other block the gridpoint is past the ends of both edges that meet there. The
// matching gridpoint of that corner across a broken crack sits there, facing the two edges equally;
// chosen afresh at each search, as the blocks rock by a hair one way and the other, its contact
// would leave the face it presses on for the open one and come back, its load dropped and given
// again. An open one goes to the squarer edge: on a face that opened, the gridpoint would otherwise
// stay off the one that presses. A corner pressed into the corner of the block diagonally across a
// crossing of two joints faces that block's two edges equally (they are its own edges'
// continuations); choosing afresh at each search would swing its force between their normals, some
// 100 degrees apart, as the blocks' small rotations reorder them: a limit cycle that keeps the
// walls of the seed cavern from settling. A tip that has slid past the corner of a face onto the
// block's side faces that face more squarely than the side, yet is not over it: taken back to the
// face at one search and handed to the side at the next, as the search's distances reorder, it
// would swing between them the same way.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace edem {

// How much squarer another edge must face the gridpoint to take a contact from its held edge [rad].
inline constexpr double kHeldFacing = 10.0 * std::numbers::pi / 180.0;

struct EdgeChoice {
  int held = -1;            // the edge the contact had, -1: none
  double own_size = 0.0;    // length of the gridpoint's summed outward normal [-]
  bool held_presses = false;  // the contact on the held edge is closed, in compression

  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();     // [m]
  double best_opposition = std::numeric_limits<double>::infinity();   // [-]
  bool best_over = false;  // the gridpoint projects onto the best edge
  double held_opposition = std::numeric_limits<double>::infinity();   // [-], infinite: not offered
  bool held_over = false;  // the gridpoint projects onto the held edge

  // `over`: the gridpoint projects onto the edge, between its ends.
  void offer(int edge, double distance, double opposition, bool over) {
    if (edge == held) {
      held_opposition = opposition;
      held_over = over;
    }
    const bool squarer = opposition < best_opposition - 1e-9;
    const bool as_square = opposition <= best_opposition + 1e-9;
    if (squarer || (as_square && distance < best_distance)) {
      best = edge;
      best_distance = distance;
      best_opposition = opposition;
      best_over = over;
    }
  }

  // The edge chosen among those offered, -1 if none was.
  int chosen() const {
    const bool offered = held_opposition < std::numeric_limits<double>::infinity();
    if (held < 0 || held == best || !offered) return best;
    if (!best_over) return held_over || held_presses ? held : best;
    if (!held_over) return best;
    return angle(held_opposition) <= angle(best_opposition) + kHeldFacing ? held : best;
  }

  // How far the edge's normal turns from squarely against the gridpoint's boundary [rad].
  double angle(double opposition) const {
    return own_size > 0.0 ? std::acos(std::clamp(-opposition / own_size, -1.0, 1.0)) : 0.0;
  }
};

}  // namespace edem
