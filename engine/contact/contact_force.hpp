// The force of one contact over one step: geometry from the current positions, the normal
// stress from the closure (joint_law.hpp), the shear force incrementally, then Coulomb slip,
// dilation and the drop to residual strength (cohesion and friction; no tension) once it slips
// or opens, or, for a softening bond, once its strength has run out (JointParams::softens).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "state/contacts.hpp"
#include "contact/facing_length.hpp"
#include "contact/joint_law.hpp"
#include "contact/past_the_end.hpp"

namespace edem {

// What a contact dissipated over a step [J/m]: by Coulomb slip (its shear spring's work less the
// energy it keeps), and by its bond (a softening bond's work past the secant; the elastic energy
// of a bond broken in tension, and a cohesive shear spring's when its faces part).
struct ContactLoss {
  double slip = 0.0, bond = 0.0;
  // What its length's change gave or took of the energy a metre it was given (Contact::given),
  // booked with the given stress (prestress), not paid for by its push.
  double given = 0.0;
};

// Coulomb's limit on a contact's shear force over `length` [N/m] at normal stress `sn`: its
// cohesion (as far as it has softened) while intact, its residual strength after.
inline double shear_limit(const Contact& c, const JointParams& p, double sn, double cohesion, double length) {
  return std::max(0.0, coulomb_strength(p, c.intact, sn, cohesion) * length);
}

// What a contact's shear force can be at most over `length` [N/m]: Coulomb's limit at its closure
// (a force carried over from a contact of another length, as a stress, keeps within it).
inline double shear_strength(const Contact& c, const JointParams& p, double length) {
  return shear_limit(c, p, c.closure > 0.0 ? normal_stress(p, c.closure) : 0.0, p.cohesion, length);
}

// A contact found again (the same gridpoint and block) as `c`, its length and edge found anew,
// keeps the state `old` had: its normal stress by its closure, its shear stress by scaling its
// force to the new length. Both lengths are taken at the overlap its force was last found at, not
// at the detection's distance to the face: near a corner that is not the overlap the force takes
// (contact_force), and a tip's length grows with it, so a tip pressed in by a corner would gain
// shear force at every detection and slip it off in its next cycle, energy made. Its next cycle
// scales the force to the overlap it finds then.
inline void keep_state(Contact& c, const Contact& old, const JointParams& p) {
  c.closure0 = old.closure0;
  c.dilation = old.dilation;
  c.closure = old.closure;
  c.sn = old.sn;
  c.us = old.us;
  c.slip = old.slip;
  c.state = old.state;
  c.intact = old.intact;
  c.opened = old.opened;
  c.share = old.share;  // what its next cycle finds the length it had by
  c.given = old.given;
  const double overlap = last_overlap(old);
  const double was = carrying_length(old, overlap), now = carrying_length(c, overlap);
  const double strength = shear_strength(c, p, now);
  c.fs = was > 0.0 ? std::clamp(old.fs * (now / was), -strength, strength) : 0.0;
}

// What a tip's normal spring stores pressed past where its tip's length starts to outgrow its own
// (tip_takes_over), before its corner's share [J/m], and that energy's slope with its own length
// [J/m^2]: the integral of its normal force over its overlap from where it touched, its own length
// up to the band, then the length that grows with the overlap, up to its reach, then the reach's.
struct TipNormal {
  double energy = 0.0, by_own = 0.0;
};
inline TipNormal tip_normal_energy(const Contact& c, const JointParams& p, double overlap) {
  const double offset = c.closure0 + c.dilation;  // closure = offset + overlap
  const double grown = c.limit * (1.0 + kReachBand);  // past it the length stays (tip_depth)
  const double from = std::max(tip_takes_over(c), -offset), to = std::max(from, std::min(overlap, grown));
  TipNormal e;
  e.by_own = normal_energy(p, offset + from);
  e.energy = c.length * e.by_own;
  // By Simpson's rule over the pieces where the length is smooth (exact for the linear law): the
  // band's two halves, the tip's, and the reach's rounded corner, wherever they fall.
  std::array<double, 5> cuts{from, overlap_at_tip_depth(c.length / c.wedge, c.limit),
                             overlap_at_tip_depth(c.length * (1.0 + kTipBand) / c.wedge, c.limit),
                             c.limit * (1.0 - kReachBand), to};
  for (double& cut : cuts) cut = std::clamp(cut, from, to);
  std::sort(cuts.begin(), cuts.end());
  for (size_t piece = 0; piece + 1 < cuts.size(); ++piece) {
    const double lo = cuts[piece], hi = cuts[piece + 1];
    if (!(hi > lo)) continue;
    constexpr int kIntervals = 16;
    const double h = (hi - lo) / kIntervals;
    double sum = 0.0, sum_by_own = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double x = lo + i * h;
      const double weight = i == 0 || i == kIntervals ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      const double sn = normal_stress(p, offset + x);
      const TipLength length = tip_length(c.length, c.wedge * tip_depth(x, c.limit).depth);
      sum += weight * sn * length.length;
      sum_by_own += weight * sn * length.by_own;
    }
    e.energy += sum * h / 3.0;
    e.by_own += sum_by_own * h / 3.0;
  }
  if (overlap > grown) {
    const TipLength at_reach = tip_length(c.length, c.wedge * c.limit);
    const double beyond = normal_energy(p, c.closure) - normal_energy(p, offset + grown);
    e.energy += at_reach.length * beyond;
    e.by_own += at_reach.by_own * beyond;
  }
  return e;
}

// The elastic energy a contact stores as its last cycle left it [J/m]: its normal spring's, the
// integral of its normal force over its overlap from where it touched (a tip's length grows with
// the overlap), and its shear spring's, fs^2 / (2 ks length).
struct ContactEnergy {
  double normal = 0.0, shear = 0.0;
};
// With `tip`, a tip's normal energy and its slope with its own length go there too when found.
inline ContactEnergy contact_energy(const Contact& c, const JointParams& p, TipNormal* tip = nullptr) {
  if (c.state == ContactState::open) return {};
  const double overlap = last_overlap(c);
  const double length = last_carrying_length(c);
  if (!(length > 0.0)) return {};
  ContactEnergy e;
  e.shear = c.fs * c.fs / (2.0 * p.ks * length);
  if (c.closure < 0.0) {  // a bond in tension, linear or on its secant
    e.normal = 0.5 * c.sn * c.closure * length;
    return e;
  }
  if (!(overlap > tip_takes_over(c))) {
    e.normal = length * normal_energy(p, c.closure);
    return e;
  }
  const TipNormal normal = tip_normal_energy(c, p, overlap);
  if (tip) *tip = normal;
  e.normal = c.share * normal.energy;
  return e;
}

// Both springs' energy together [J/m].
inline double stored_in(const Contact& c, const JointParams& p) {
  const ContactEnergy e = contact_energy(c, p);
  return e.normal + e.shear;
}

// The forces a contact gives its nodes besides its force on the gridpoint and that force's
// reaction on the edge point under it [N/m], by role (kContactRoles, x and y each): the couple its
// shear force leaves, acting as far off the edge as the gridpoint is pressed in, on the edge's
// ends; and for a contact whose length follows its facing length (Contact::per_facing), its
// stored energy's slope with respect to the positions of the nodes that set that length, at its
// closure and shear stress.
struct NodePush {
  double on[2 * kContactRoles] = {};
};

// A contact's force on its gridpoint, the reaction on its edge's ends split by where it projects,
// and the rest it gives its nodes (NodePush): by role (kContactRoles), x and y [N/m].
[[gnu::always_inline]] inline void contact_push(const Contact& c, const NodePush& extra,
                                                double p[2 * kContactRoles]) {
  const double wa = -(1.0 - c.t), wb = -c.t;
  p[0] = c.fx + extra.on[0];
  p[1] = c.fy + extra.on[1];
  p[2] = wa * c.fx + extra.on[2];
  p[3] = wa * c.fy + extra.on[3];
  p[4] = wb * c.fx + extra.on[4];
  p[5] = wb * c.fy + extra.on[5];
  for (int k = 6; k < 2 * kContactRoles; ++k) p[k] = extra.on[k];
}

// Whether the end a (at_a) or b of edge `e` is a convex corner of the rock: a corner of its block
// whose edge beside is free. Behind a glued edge beside the rock goes on (a glued tip, whose edge
// beside is glued too, has rules of its own).
inline bool rock_corner(const ContactEdge* edges, const ContactEdge& e, bool at_a) {
  return at_a ? e.corner_a && edges[e.prev].touchable : e.corner_b && edges[e.next].touchable;
}

// How deep the gridpoint is inside the edge's block [m]: behind the edge's line and behind the
// line of the edge beside it at each corner of the rock the edge ends in (rock_corner: the block
// is convex there). The overlap the force takes can run
// deeper beside a corner: its cap adds the span the force fades over, and a tip whose edges lead
// past a sharp corner carries only its share there. A gridpoint beside the block is not in it,
// however far behind the edge's line (the overlap watchdog asks).
inline double depth_in_block(const Contact& c, const ContactEdge* edges, const double* origin,
                             const double* u) {
  const auto at = [&](int node) {
    const size_t k = 2 * static_cast<size_t>(node);
    return std::array<double, 2>{origin[k] + u[k], origin[k + 1] + u[k + 1]};
  };
  const std::array<double, 2> p = at(c.node);
  const auto behind = [&](int from, int to) {  // the gridpoint's depth behind the line from -> to
    const std::array<double, 2> f = at(from), t = at(to);
    const double dx = t[0] - f[0], dy = t[1] - f[1];
    return ((p[1] - f[1]) * dx - (p[0] - f[0]) * dy) / std::hypot(dx, dy);
  };
  const ContactEdge& e = edges[c.edge];
  double depth = behind(e.a, e.b);
  if (rock_corner(edges, e, true)) depth = std::min(depth, behind(edges[e.prev].a, e.a));
  if (rock_corner(edges, e, false)) depth = std::min(depth, behind(e.b, edges[e.next].b));
  return depth;
}

// Updates `c` and its force on the gridpoint (c.fx, c.fy) from the node positions, origin + u,
// and velocities `v`; returns the overlap, how far the
// gridpoint is inside the edge's block [m] (negative: a gap). `edges`: all of them (the edge is
// edges[c.edge]; past a corner its neighbour matters too). Adds what it dissipates to `lost`.
// With `pushing` (the caller's, zeroed) it puts there the rest of its forces on its nodes
// (NodePush); without, only the gridpoint's force and its reaction are given.
[[gnu::always_inline]] inline double contact_force(Contact& c, const ContactEdge* edges, const JointParams& p,
                                                   const double* origin, const double* u,
                                                   const double* v, double dt, ContactLoss& lost,
                                                   NodePush* pushing = nullptr) {
  const ContactEdge& e = edges[c.edge];
  const size_t n = static_cast<size_t>(c.node), a = static_cast<size_t>(e.a), b = static_cast<size_t>(e.b);
  const auto x = [&](size_t dof) { return origin[dof] + u[dof]; };
  const double xa = x(2 * a), ya = x(2 * a + 1);
  const double dx = x(2 * b) - xa, dy = x(2 * b + 1) - ya;
  const double px = x(2 * n) - xa, py = x(2 * n + 1) - ya;
  const double len = std::sqrt(dx * dx + dy * dy);
  double sx = dx / len, sy = dy / len;  // along the edge
  // The length last cycle's force was found over and the overlap it was at, then this cycle's
  // length as the gridpoint's edges face the edge now (facing_length.hpp).
  const double length_before = last_carrying_length(c);
  const double overlap_before = last_overlap(c);
  double facing = 0.0;
  const double own_length_before = c.length;
  FacingSlope facing_slope;
  if (c.per_facing > 0.0) {
    const size_t fa = static_cast<size_t>(c.far_a), fb = static_cast<size_t>(c.far_b);
    const FacingNodes nodes{{x(2 * n), x(2 * n + 1)}, {x(2 * fa), x(2 * fa + 1)}, {x(2 * fb), x(2 * fb + 1)},
                            {xa, ya},
                            {x(2 * b), x(2 * b + 1)},
                            e.corner_a || c.pair_at_a,
                            e.corner_b || c.pair_at_b,
                            c.half_a,
                            c.half_b};
    facing = facing_length(nodes, pushing ? &facing_slope : nullptr);
    c.length = c.per_facing * facing;
  }
  double nx = sy, ny = -sx;             // out of the edge's block
  const double t_line = (px * sx + py * sy) / len;
  const double t = std::clamp(t_line, 0.0, 1.0);
  double gap = px * nx + py * ny;  // from the edge's line
  // Past a bent end (no convex corner, no straight run) and the neighbour's end too: the vertex's
  // distance. Not for one of a corner's two contacts in a corner (Contact::split): each keeps to
  // its own face's line, and at the vertex, where the corner sits, the vertex's direction is
  // round-off's.
  if (!c.split && ((t_line < 0.0 && e.bent_a) || (t_line > 1.0 && e.bent_b))) [[unlikely]] {
    const bool at_a = t_line < 0.0;
    const size_t vertex = at_a ? a : b;
    const size_t far = static_cast<size_t>(at_a ? edges[e.prev].a : edges[e.next].b);
    PastTheEnd end;
    if (past_the_end(x(2 * n) - x(2 * vertex), x(2 * n + 1) - x(2 * vertex + 1), x(2 * far) - x(2 * vertex),
                     x(2 * far + 1) - x(2 * vertex + 1), sx, sy, at_a, end)) {
      nx = end.nx;
      ny = end.ny;
      sx = -ny;  // the normal turned back, as the edge's is its direction turned clockwise
      sy = nx;
      gap = end.gap;
    }
  }
  // Caps the depth at the gridpoint's depth inside the line from node `from` to `to` of the
  // edge's block, less `span`. Where that cap holds and `turn`, the normal force acts along that
  // line's normal: the force is then the slope of the energy the depth gives (the shear force
  // stays along the edge).
  const auto from_line = [&](size_t from, size_t to, double span, bool turn) {
    const double fx = x(2 * from), fy = x(2 * from + 1);
    const double ndx = x(2 * to) - fx, ndy = x(2 * to + 1) - fy;
    const double nlen = std::sqrt(ndx * ndx + ndy * ndy);
    const double out = ((x(2 * n) - fx) * ndy - (x(2 * n + 1) - fy) * ndx) / nlen - span;
    if (!(out > gap)) return;
    gap = out;
    if (turn) {
      nx = ndy / nlen;
      ny = -ndx / nlen;
    }
  };
  // The same by the line of the edge beside this one at its end a (or b).
  const auto from_neighbour = [&](bool at_a, double span, bool turn) {
    from_line(static_cast<size_t>(at_a ? edges[e.prev].a : e.b), static_cast<size_t>(at_a ? e.a : edges[e.next].b),
              span, turn);
  };
  // Past the end of the edge at a convex corner of its block, the gridpoint's share of the
  // contact length shrinks with the distance past the corner and is gone at twice its length
  // (its half-edges then no longer lie over the block): the force fades as a face slides off a
  // corner instead of dropping at once. Faces zoned alike (zoning.hpp) put the gridpoints at a
  // joint's ends exactly on the corners, where any all-or-nothing rule would flicker: the share
  // starts and ends level (a smooth step over the span), so the push below it gives is nothing
  // on the corner, whichever side of it round-off puts the gridpoint.
  double share = 1.0, fade_slope = 0.0;  // the share, and its fall a metre further out
  double fade_by_length = 0.0;  // its rise as a span set by the length grows [1/m]
  const double fade = std::max(c.length, c.wedge * c.limit);  // a tip's: at its deepest
  const bool past = (t_line < 0.0 && e.corner_a) || (t_line > 1.0 && e.corner_b);
  if (past) {
    const double beyond = (t_line < 0.0 ? -t_line : t_line - 1.0) * len;
    const double out = fade > 0.0 ? std::min(1.0, beyond / (2.0 * fade)) : 1.0;  // of the span
    share = 1.0 - out * out * (3.0 - 2.0 * out);
    fade_slope = out < 1.0 ? 6.0 * out * (1.0 - out) / (2.0 * fade) : 0.0;
    if (fade == c.length) fade_by_length = 2.0 * fade_slope * out;
  }
  const double fade_share = share;
  // Past the corner the far extension of this edge's line must not press in a gridpoint that
  // has gone beside the block (a wall sliding past the corner of a floor that heaved), nor,
  // within the edge near the corner, one beside a thin tip that has sunk into its own block's
  // face: it is inside by at most its depth inside the neighbouring edge's line plus the span
  // the force fades over (so a gridpoint on the corner, inside or out by round-off, keeps its
  // contact). Both corners cap it, wherever over the edge it is: the lesser depth holds, so it
  // does not jump at the face's middle nor at any distance from a corner (a cap within a reach
  // alone would switch on and off across it, and a gridpoint rocking there would make energy at
  // every crossing). Only a corner of the rock caps (rock_corner); a glued tip's end has the rule
  // below instead. A corner whose edge beside is glued, the rock going on there past it, caps
  // nothing: behind that edge's line the gridpoint is in the rock glued beside, as deep as the
  // face's line says, and capped by the glued line a gridpoint driven along it (a falling block's
  // apex into a crack's mouth on a floor) was held back by its distance from that line only, the
  // force turned across the line, and went on in unchecked (1.1 m in the seed cavern's Case 3 at
  // 262 m). Past the corner the share fades and the glued block's own contact carries it.
  const bool cap_a = rock_corner(edges, e, true) && (t_line < 0.0 || gap < 0.0);
  const bool cap_b = rock_corner(edges, e, false) && (t_line > 1.0 || gap < 0.0);
  if (!c.split) {
    if (cap_a) from_neighbour(true, 2.0 * fade, true);
    if (cap_b) from_neighbour(false, 2.0 * fade, true);
  }
  // One of a corner's two contacts in a corner (Contact::split) past the end where its face meets
  // the other's is over the other face: it is in by at most its depth there. By its own face's
  // line, run on past that end, a gridpoint sliding along the other face would be in by its
  // distance from the end times the sine of the turn between the faces.
  if (c.split && (t_line < 0.0 || t_line > 1.0)) [[unlikely]] from_neighbour(t_line < 0.5, 0.0, false);
  // Behind the edge (over it or past its end) yet out of the line of the glued edge at a glued
  // tip (ContactEdge::glued_tip_a, b), at its end or at the end of the straight run it is part of
  // (glued_line_a, b), is past the tip into the block glued there, whose own faces carry the
  // gridpoint. Here it is inside by at most its depth inside the glued edge's line, no span
  // added, so the force goes to nothing as it crosses that line and comes back as it returns: the
  // contact stays, never dropped and made again with a prestress. The same depth on both sides of
  // the edge's end, and of each vertex of the run: a depth that jumped there would make energy at
  // every crossing.
  if ((e.glued_line_a >= 0 || e.glued_line_b >= 0) && gap < 0.0) [[unlikely]] {
    for (const int glued : {e.glued_line_a, e.glued_line_b}) {
      if (glued < 0) continue;
      const ContactEdge& g = edges[glued];
      from_line(static_cast<size_t>(g.a), static_cast<size_t>(g.b), 0.0, false);
    }
  }
  // A tip whose edges all lead out past a sharp corner of the edge (Contact::leads_past_a, b)
  // is over the block only short of it: pressed in by d, its overlap runs about 2 wedge d from its
  // apex towards the corner, deepest at the apex, and only the part before the corner presses on
  // the block: its share grows with that part of the chord, q, as a smooth step, 1 that far from
  // the corner, 0 at the corner and beyond, level at both ends as the fade's is. The fade above
  // would have the face's line, run on past the corner, push the corner of a block that stands
  // beside, on the block next to this one (a slipped crossing). Short of the corner a length of
  // its own (half-edges along the face) carries in full: only the tip's part beyond it is cut.
  // The share hangs on the gridpoint's distance from the corner and on its depth; its slopes with
  // them (per metre) give the push that makes the force its energy's slope (below). Level at the
  // corner, that push is nothing there, where the contact ends: a push that stopped short there
  // would do work at every crossing of a gridpoint rocking over the corner.
  double cut_by_place = 0.0, cut_by_depth = 0.0, share_by_length = 0.0;
  bool corner_at_a = false;
  if (c.leads_past_a || c.leads_past_b) [[unlikely]] {
    const double to_a = c.leads_past_a ? t_line * len : INFINITY;
    const double to_b = c.leads_past_b ? (1.0 - t_line) * len : INFINITY;
    const double from_corner = std::min(to_a, to_b);
    corner_at_a = to_a <= to_b;
    const double depth = -gap;
    const TipDepth grown = tip_depth(depth, c.limit);
    const double tip = c.wedge * grown.depth, tip_by_depth = c.wedge * grown.slope;
    const double q = tip > 0.0 ? std::clamp(from_corner / (2.0 * tip), 0.0, 1.0) : 1.0;
    const double tip_share = from_corner > 0.0 ? q * q * (3.0 - 2.0 * q) : 0.0;
    const double own = !(from_corner > 0.0) ? 0.0 : tip > c.length ? share * c.length / tip : share;
    const double cut = std::min(share, tip_share);
    // Slopes of the own length's share and of the cut tip's, with depth, place and own length.
    const bool own_moves = from_corner > 0.0 && tip > c.length;
    const double own_by_depth = own_moves ? -own / tip * tip_by_depth : 0.0;
    const double own_by_length = own_moves ? share / tip : 0.0;
    const bool cut_moves = from_corner > 0.0 && tip_share < share && q < 1.0;
    const double cut_by_q_place = cut_moves ? 3.0 * q * (1.0 - q) / tip : 0.0;
    const double cut_by_q_depth = cut_moves ? -6.0 * q * q * (1.0 - q) / tip * tip_by_depth : 0.0;
    // The larger of the two, its corner rounded over a band a tenth of their mean wide where both
    // move: where one takes over from the other the share's slope must not jump, or a gridpoint
    // rocking across the switch is pushed by a step that one sample a cycle integrates wrongly,
    // energy made each cycle. Where either is at its cap it is the share, as given.
    const double band = cut_moves && own_moves ? 0.05 * (own + cut) : 0.0, apart = own - cut;
    const double overlap_of_band = std::max(0.0, band - std::fabs(apart));
    share = std::max(own, cut);
    double by_own = apart > 0.0 ? 1.0 : 0.0, by_cut = 1.0 - by_own;
    if (overlap_of_band > 0.0) {
      const double h = overlap_of_band, side = apart > 0.0 ? 1.0 : -1.0;
      share += h * h / (4.0 * band);
      const double level = 0.05 * h * h / (4.0 * band * band);  // through the band's width
      by_own += h * (0.05 - side) / (2.0 * band) - level;
      by_cut += h * (0.05 + side) / (2.0 * band) - level;
    }
    cut_by_place = by_cut * cut_by_q_place;
    cut_by_depth = by_own * own_by_depth + by_cut * cut_by_q_depth;
    share_by_length = by_own * own_by_length;
  }
  // The gridpoint's velocity along the face against that of the edge's block where the gridpoint
  // is: the edge point's under it, and what the edge's turn adds at the gridpoint's offset `r`
  // from there (as far as it is pressed in, and past a corner how far beyond it). Two blocks
  // pressed together and turned as one do not shear; by the edge point's velocity alone they
  // would, by the overlap times the angle.
  const double rx = px - t * dx, ry = py - t * dy;
  const double dvx = v[2 * b] - v[2 * a], dvy = v[2 * b + 1] - v[2 * a + 1];
  const double turn_rate = (dx * dvy - dy * dvx) / (len * len);  // the edge's [rad/s]
  const double offset_across = rx * sy - ry * sx;                 // r x s
  const double rvx = v[2 * n] - ((1.0 - t) * v[2 * a] + t * v[2 * b]);
  const double rvy = v[2 * n + 1] - ((1.0 - t) * v[2 * a + 1] + t * v[2 * b + 1]);
  const double dus = (rvx * sx + rvy * sy - turn_rate * offset_across) * dt;
  // The state the last step left, for what this one dissipates.
  const double closure_before = c.closure, sn_before = c.sn, fs_before = c.fs;
  const bool open_before = c.state == ContactState::open, intact_before = c.intact;
  c.t = t;
  const double share_before = c.share;
  c.share = share;
  c.us += dus;
  // Dilation pushes the faces apart: at a given gap the joint is that much more closed.
  c.closure = c.closure0 - gap + c.dilation;

  double sn = normal_stress(p, c.closure);
  const double length = share * carrying_length(c, -gap);
  bool open = !(length > 0.0);  // past the corner, or a tip not pressed in
  double left = 1.0;            // of a softening bond's strength (joint_law.hpp)
  // (A bond with no tensile strength between faces that start together must not break on the
  // round-off of its gap.)
  const bool opening = c.closure < -1e-9 * c.limit;
  if (!open && c.intact && p.softens) [[unlikely]] {
    if (opening) c.opened = std::max(c.opened, -c.closure);
    left = bond_left(p, c.opened, c.slip);
    if (!(left > 0.0)) {
      c.intact = false;
      open = c.closure <= 0.0;
    } else if (c.closure < 0.0) {  // towards zero opening from the largest (secant)
      const double largest = std::max(c.opened, p.tension / p.kn_zero);
      sn = largest > 0.0 ? p.tension * left * c.closure / largest : 0.0;
      // The normal spring's mid-step work less the change of its (secant) energy.
      lost.bond += 0.5 * length * (sn_before * c.closure - sn * closure_before);
    }
  } else if (!open && c.intact && sn < -p.tension && opening) {  // fails in tension: gone
    c.intact = false;
    open = true;
  } else if (!open && !c.intact && c.closure <= 0.0) {
    open = true;
  }
  if (open) {
    if (!open_before && length_before > 0.0) {
      // Faces that part keep nothing: a bond's tension and a cohesive shear spring's energy go.
      lost.bond += fs_before * fs_before / (2.0 * p.ks * length_before);
      if (intact_before && closure_before < 0.0) lost.bond += 0.5 * sn_before * closure_before * length_before;
    }
    c.sn = 0.0;
    c.fs = 0.0;
    c.state = ContactState::open;
    c.fx = c.fy = 0.0;
    return share > 0.0 ? -gap : 0.0;
  }
  const double ks = p.ks * length;
  // Its length changes past a corner, with its facing length or its share: it keeps its shear
  // stress, as its normal stress keeps to its closure (what that changes in its energy the
  // length's push below pays for). A tip's length changes with its depth too, and for that part
  // it keeps its shear spring's energy, fs^2 / (2 ks length), so the force scales as the root of
  // the length: a stress kept there would store tau^2 / (2 ks) a metre the tip grows, for the
  // normal force to pay, and on a tip a fraction of a millimetre long, carrying megapascals, that
  // payment is hundreds of times its normal force and jumps across the band where its tip's
  // length takes over (tip_length): stiffer than its gridpoint's mass is scaled for, it chatters
  // and makes energy. Kept energy needs no force, and pressed in and back it is the same again.
  double fs_start = length_before > 0.0 ? fs_before * (length / length_before) : 0.0;
  if (c.wedge > 0.0 && length_before > 0.0 && length > 0.0) {
    const double at_depth_before = share * carrying_length(c, overlap_before);
    if (at_depth_before > 0.0)
      fs_start = fs_before * (at_depth_before / length_before) * std::sqrt(length / at_depth_before);
  }
  const double trial = fs_start - ks * dus;
  const double cohesion =
      p.softens ? p.residual_cohesion + (p.cohesion - p.residual_cohesion) * left : p.cohesion;
  const double limit = shear_limit(c, p, sn, cohesion, length);
  if (std::fabs(trial) > limit) {
    const double plastic = (std::fabs(trial) - limit) / ks;
    c.fs = std::copysign(limit, trial);
    // The shear spring's mid-step work, less what it keeps.
    lost.slip += -0.5 * (fs_start + c.fs) * dus - (c.fs * c.fs - fs_start * fs_start) / (2.0 * ks);
    c.slip += plastic;
    if (sn > 0.0) c.dilation += p.tan_dilation * plastic;
    c.intact = c.intact && p.softens && bond_left(p, c.opened, c.slip) > 0.0;
    c.state = ContactState::slip;
  } else {
    c.fs = trial;
    c.state = c.intact ? ContactState::bonded : ContactState::elastic;
  }
  c.sn = sn;
  double fn = sn * length;
  // A tip's length hangs on its depth and on its own length (tip_length); its shear spring's
  // energy changes only with the own length's part, fs^2 / (2 ks length^2) a metre, which the
  // length's push pays (below).
  const double depth = -gap;
  const bool tip_past = c.wedge > 0.0 && depth > tip_takes_over(c);  // its tip's length counts
  TipLength tip_at;                                                   // its length's slopes at this depth
  double shear_per_length = 0.0;                                      // fs^2 / (2 ks length^2) [J/m^2]
  if (tip_past) [[unlikely]] {
    tip_at = tip_length(c.length, c.wedge * tip_depth(depth, c.limit).depth);
    shear_per_length = c.fs * c.fs / (2.0 * p.ks * length * length);
  }
  c.fx = fn * nx + c.fs * sx;
  c.fy = fn * ny + c.fs * sy;
  // What its springs store as this cycle leaves them, found once when first asked (a tip's normal
  // spring's is an integral), with a tip's normal energy's slope with its own length.
  ContactEnergy energy_now;
  TipNormal tip_normal;
  bool energy_known = false;
  const auto stored_now = [&]() {
    if (!energy_known) energy_now = contact_energy(c, p, &tip_normal), energy_known = true;
    return energy_now.normal + energy_now.shear;
  };
  // Past the corner its springs' energy is share x what they would store over the whole length:
  // the fade's force is that energy's slope, a push along the edge away from the corner. Without
  // it the energy a face sliding off a corner under load stores would vanish as its share goes.
  // Only what they store beyond the state the contact was given (Contact::given), as with its
  // length's push below: what the fade takes of the given part is the given stress's. Pushed on
  // too, a contact with a length of micrometres (a gridpoint whose half-edge reaches a face's end
  // just past a corner) would push with the whole prestress a metre of it holds, some 1e5 N/m,
  // whatever its length, as its fade's span is its length.
  const bool fading = past && share > 0.0 && share == fade_share;
  if (fading) [[unlikely]] {
    const double beyond = std::max(0.0, stored_now() / share - c.length * c.given);
    const double push = beyond * fade_slope * (t_line < 0.0 ? -1.0 : 1.0);
    c.fx += push * sx;
    c.fy += push * sy;
    lost.given += c.given * c.length * (share - share_before);
  }
  // A tip short of a sharp corner stores share x what its springs would over the whole tip, and its
  // share hangs on where it is: the force is that energy's slope, a push along the edge towards
  // the corner, where the share falls, and the share's change with the depth added to the normal
  // force. Without it the force would not be the slope of any energy, and two corners pressed into
  // each other at a slipped joint crossing, rocking, would make energy at every round. As with the
  // fade, only what the springs store beyond the given state: the given part's change goes to the
  // given stress's account. Its reaction along the edge goes to the corner, whose place sets the
  // distance, and the couple it leaves with it, as the shear force's (below).
  double along = 0.0, whole = 0.0;
  if (!fading && (cut_by_place != 0.0 || cut_by_depth != 0.0 || share_by_length != 0.0) && share > 0.0)
      [[unlikely]] {
    whole = std::max(0.0, stored_now() / share - c.length * c.given);
    along = -whole * cut_by_place * (corner_at_a ? 1.0 : -1.0);
    const double out = whole * cut_by_depth;
    c.fx += along * sx + out * nx;
    c.fy += along * sy + out * ny;
    lost.given += c.given * c.length * (share - share_before);
    if (pushing) {
      const double moved = corner_at_a ? c.t : -(1.0 - c.t);  // of the push's reaction, from the far end
      pushing->on[2] -= moved * along * sx;
      pushing->on[3] -= moved * along * sy;
      pushing->on[4] += moved * along * sx;
      pushing->on[5] += moved * along * sy;
    }
  }
  // Its energy is its length times what it stores per metre, at the closure and shear stress it
  // has (a tip pressed past its own length: up to the overlap where the tip's took over): the
  // slope of that energy with its facing length pushes the nodes that set it. Without it the
  // energy a turning gridpoint's, or one sliding past a corner, gains or loses with its length
  // would come from nowhere.
  if (pushing && facing > 0.0) {
    // Only what it stores beyond the state it was given: a given stress, in equilibrium as given,
    // is not pushed on; what its length changes of it goes to the given stress's account.
    // A contact come off its given state (unloaded, opened) keeps no more of it than it stores:
    // its length's push never pulls to lengthen it.
    const double stored = stored_now();
    if (share * c.length * c.given > stored) c.given = share * c.length > 0.0 ? stored / (share * c.length) : 0.0;
    const double beyond = stored - share * c.length * c.given;
    double w = beyond / facing;  // [J/m per m of facing length]
    // Past a corner the span its share fades over is its length, which the facing length sets.
    // The given part's change with the length, its share's span included.
    double given_by_length = c.given * share;
    if (tip_past) {
      // A tip pressed past where its tip's length takes over: its energy hangs on its own length
      // through the part of its overlap its own length carried (tip_normal_energy, found with
      // `stored` above), and its shear spring's through its length at this depth. Short of a sharp
      // corner its share hangs on its own length too (own length / tip).
      const double own_part = tip_normal.by_own + shear_per_length * tip_at.by_own;
      w = c.per_facing * share * std::max(0.0, own_part - c.given);
      w += c.per_facing * whole * share_by_length;
    } else if (fading) {
      w += beyond / share * fade_by_length * c.per_facing;
      // (Its share's change with the length is booked with the fade's above.)
    }
    lost.given += given_by_length * (c.length - own_length_before);
    const double* slopes[kContactRoles] = {facing_slope.p, facing_slope.a, facing_slope.b, facing_slope.far_a,
                                           facing_slope.far_b};
    for (int role = 0; role < kContactRoles; ++role)
      for (int k = 0; k < 2; ++k) pushing->on[2 * role + k] = -w * slopes[role][k];
  }
  // The shear force on the gridpoint and its reaction act `r` apart: the couple fs (r x s) they
  // leave is balanced by forces across the edge on its ends, whose work over the edge's turn is
  // what the turn's part of the shear displacement above takes from the shear spring. A tip's push
  // along the edge leaves the same couple, and turned with the edge it stores nothing more.
  if (pushing) {
    const double across = (c.fs + along) * offset_across / (len * len);  // x (dy, -dx) on b, minus on a
    pushing->on[2] -= across * dy;
    pushing->on[3] += across * dx;
    pushing->on[4] += across * dy;
    pushing->on[5] -= across * dx;
  }
  return -gap;
}

}  // namespace edem
