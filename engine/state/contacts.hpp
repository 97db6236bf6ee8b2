// Contacts between blocks: a gridpoint of one block against an edge of another, as UDEC's
// sub-contacts of deformable blocks.
//
// Every gridpoint on a block boundary that is not glued looks for the nearest edge of each
// other block within its reach; both sides of a joint do so, each with half the contact length,
// so that the two faces carry the joint's stiffness together whatever their zoning. A contact's
// length is the part of its gridpoint's boundary that faces that block: of half of each adjacent
// edge, the part that lies over the block's faces, projected on the contact plane (so a
// gridpoint facing the end of one block and the start of the next shares between them, and the
// length moves smoothly as it slides past a joint crossing); where two blocks' faces both lie
// under a half-edge, the one nearer its quarter point takes more, and one the half-edge does not
// face takes none (detect.cpp, kShareBand, kNearestFacing).
// Between detections the length follows where the nodes are: it is held in proportion to the
// facing length, what the gridpoint's half-edges give over the face's line, clipped at its
// convex corners (facing_length.hpp), and the slope of the contact's stored energy with that
// length pushes the nodes that set it (contact_force.hpp). A contact found again finds close to
// the length it has (the detection walks the outline, the facing length one line), and what a
// turn of the blocks (at an oblique corner) or a slide past a corner changes in its energy, at
// first order, is work its force did, not a jump at the detection.
//
// A gridpoint at a convex corner whose edges both leave the other block's face (a tip driven in
// point first) has almost no such length, yet its boundary crosses the face over a chord that
// grows with how deep it is in: pressed in by d, the overlap is a triangle of d times half that
// chord, which is what a penalty interface pushes back on. Its length is then at least `wedge`
// times d (half the chord per unit depth), up to a quarter of its edges at the watchdog's depth,
// a face's share. A corner with one edge along the face (up to 10 deg into it) is such a tip with
// the most: a corner pushed into the face of the block diagonally across a slipped joint crossing,
// its half-edge along the joint carried by the block beside (detect.cpp, tip_wedge). A tip whose
// edges all lead out past a sharp corner of the face it is pressed into lies over that block only
// short of the corner; beyond it, it stands beside the block and takes nothing from the face's
// line run on (contact_force.hpp).
//
// The contacts of a block are found again (refresh_contacts) when its boundary has moved an
// eighth of the smallest reach since it was last marked, with those of the blocks near it; all
// of them when most of the model is due, or the list is no longer current. Right after a full
// search nothing is due until some block has moved a quarter of it, as when only full searches
// were done: a region that moves as a whole is not searched twice as often. The state of a
// contact that persists is carried over, by its gridpoint and the other block, as stresses: its
// length found again, its closure is kept and its shear force scaled with the length (within its
// strength), while its new edge lies along the same face as its old one (normals within 20
// degrees); found on another face of the block it starts anew. A contact made where the same
// two blocks already press together nearby, along the same joint, takes their faces' state:
// their closure at zero gap and their shear traction (detect.cpp, LoadedFaces); a gridpoint
// sliding past a joint crossing onto the next block, or a face sliding onto more of its
// neighbour, carries the joint's stress at once. Finding only where things move keeps a few
// falling blocks from costing a search of the whole model every few cycles. Between rebuilds the
// edge of a contact is fixed; a gridpoint that slides past the edge's end is held at the end, at
// most an eighth of an edge away. At a
// rebuild a contact keeps its edge while the gridpoint projects onto it and no other it projects
// onto faces it much more squarely (edge_choice.hpp), and that edge stays on offer a band further
// than the others, and while it presses further by its law's curve closure (detect.cpp): a corner
// pressed into a corner, or a tip past the corner of a face, would otherwise swing between two
// edges, and a corner sunk into a soft joint's face would leave it for the side face it lies on.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "geom/block_set.hpp"

namespace edem {

// A block boundary edge as the contacts see it. The block is on its left (outer loops run
// counter-clockwise, holes clockwise), so its outward normal is the edge direction turned
// clockwise.
struct ContactEdge {
  int a = -1, b = -1;        // solver nodes, in loop order
  int block = -1;            // mesh block
  int prev = -1, next = -1;  // the neighbouring edges of its loop
  // Whether its end is a convex corner of its block (the boundary turns by more than 10
  // degrees there), not a point where it goes on (nearly) straight.
  bool corner_a = false, corner_b = false;
  // Whether the boundary turns at its end a (b) without making a convex corner there: in, or out
  // by less. Past such an end, and past the neighbouring edge's too, a gridpoint is measured from
  // the vertex (past_the_end.hpp); along a straight run the edge's line is the boundary.
  bool bent_a = false, bent_b = false;
  // Whether its end a (b) is the tip of an acute piece of glued rock: a convex corner of its
  // block where the edge beside is glued (an intact potential crack, a region outline), and the
  // outline of the blocks glued together there turns outward too (it does not run on along this
  // edge's line). Past the glued edge's line a gridpoint is in the block glued beside, not in this
  // one (contact_force.hpp).
  bool glued_tip_a = false, glued_tip_b = false;
  // The glued edge at the glued tip its end a (b) leads to along a straight run of its block's
  // boundary, this edge's own at its tip (-1: none): a gridpoint past that glued edge's line is
  // beside this block however far along the run it is found (contact_force.hpp).
  int glued_line_a = -1, glued_line_b = -1;
  bool touchable = false;    // not glued
  EdgeOrigin origin;
  int material = -1;         // joint material (jassign), -1: none
};

// The boundaries of the blocks, built once per mesh.
struct ContactBoundary {
  std::vector<ContactEdge> edges;
  std::vector<int> block_first_edge;  // per mesh block, + 1
  // Gridpoints (solver nodes) on at least one touchable edge, ascending; per such node (CSR):
  // its touchable edges and the blocks it belongs to.
  std::vector<int> nodes;
  std::vector<int> edge_first, node_edges;
  std::vector<int> block_first, node_blocks;
  std::vector<double> reach;  // per node: half its shortest touchable edge [m]
  double min_reach = 0.0;     // [m]
  double median_edge = 0.0;   // the median length of the touchable edges [m]
  int touchable_blocks = 0;   // blocks with a touchable edge: below two, no contacts ever
};

enum class ContactState : std::uint8_t { bonded, elastic, slip, open };

struct Contact {
  int node = -1;       // the gridpoint
  int block = -1;      // a block it belongs to
  int other = -1;      // the block of the edge
  int edge = -1;       // index into ContactBoundary::edges
  int material = -1;   // joint material
  // 0; 1 for a gridpoint's second contact with the same block, on another face of it: a corner
  // in a corner, each of the gridpoint's half-edges along its own face (detect.cpp, second_face).
  int face = 0;
  bool split = false;  // one of such two: it keeps to its own face's line (contact_force.hpp)
  double length = 0.0; // [m]
  // The ends of the gridpoint's own edges, before it (far_a) and after it (far_b) along its loop,
  // and its length per unit facing length (facing_length.hpp), which it follows between
  // detections, and across them while a detection measures its length within 10 % of that
  // (detect.cpp, follows_as_before). 0: held as found (a gridpoint where glued blocks meet, with
  // more own edges).
  int far_a = -1, far_b = -1;
  double per_facing = 0.0;
  // Whether its facing length counts the half-edge towards far_a (far_b): one of a corner's two
  // contacts in a corner (split) counts only the one along its own face; and whether that face
  // meets the pair's other at end a (b) of its edge, where its facing length then stops: past it
  // the half-edge is over the other face.
  bool half_a = true, half_b = true;
  bool pair_at_a = false, pair_at_b = false;
  // What it stored a metre in the state it was given (insitu{}, a fresh crack's traction, a loaded
  // joint's faces) [J/m^2]: its length's push pays only for what it stores beyond that, the rest
  // is the given stress's (contact_force.hpp).
  double given = 0.0;
  double wedge = 0.0;  // a tip's length per unit overlap (0: not a tip) [-]
  double limit = 0.0;  // the gridpoint's reach: how deep a tip's length grows, where its corners fade [m]
  double t = 0.0;      // where the gridpoint projects on the edge, 0 at a, 1 at b
  double share = 1.0;  // of `length` still over the edge's block (near or past a corner: less) [-]
  double closure0 = 0.0;  // closure at zero gap: the in-situ prestress [m]
  double dilation = 0.0;  // opening from dilation [m]: closure = closure0 - gap + dilation
  double closure = 0.0;   // last closure, positive pressing [m]
  double sn = 0.0;        // last normal stress, compression positive [Pa]
  double fs = 0.0;        // shear force on the gridpoint along the edge direction [N/m]
  double us = 0.0;        // shear displacement since it formed [m]
  double slip = 0.0;      // plastic shear displacement, accumulated as a length [m]
  double opened = 0.0;    // a softening bond's largest opening, the closure's negative [m]
  double fx = 0.0, fy = 0.0;  // force on the gridpoint this cycle [N/m]
  ContactState state = ContactState::elastic;
  bool intact = false;    // still has its cohesion and tensile strength
  // A tip whose edges all lead out past end a (b) of the edge, a sharp corner of its block, none
  // back over the block: beyond that corner nothing of it lies over the block, and short of it
  // only its own length and part of the tip's (contact_force.hpp).
  bool leads_past_a = false, leads_past_b = false;
};

// The nodes a contact pushes (ContactSet::gather): its gridpoint, its edge's ends a and b, and
// the far ends of the gridpoint's own edges (Contact::far_a, far_b).
constexpr int kContactRoles = 5;

// A contact's own energy balance, kept while energy{ by_contact = true }: the energy it made
// since the balance started [J/m] (its stored energy's change and what it dissipated, less the
// work its nodes did on it, each step as the balance books it), and the force its last cycle
// pushed its nodes with, for that work over the next step.
struct ContactBook {
  double made = 0.0;
  double push[2 * kContactRoles] = {};
  int nodes[kContactRoles] = {-1, -1, -1, -1, -1};  // by role (kContactRoles); -1: none, or no cycle yet
};

// The work of a book's force on its nodes over half a step at velocities `v` (dt: the step) [J/m].
inline double half_step_work(const ContactBook& book, const double* v, double dt) {
  double work = 0.0;
  for (int k = 0; k < kContactRoles; ++k) {
    if (book.nodes[k] < 0) continue;
    const size_t n = static_cast<size_t>(book.nodes[k]);
    work += 0.5 * dt * (book.push[2 * k] * v[2 * n] + book.push[2 * k + 1] * v[2 * n + 1]);
  }
  return work;
}

struct ContactSet {
  std::vector<Contact> list;  // ordered by gridpoint, then other block, then face
  // Per contact, in list order, while contacts book their own energy (EnergyLedger::by_contact,
  // ContactBook); else empty.
  std::vector<ContactBook> books;
  // Per node (CSR over all nodes): the contact forces it takes, as contact * kContactRoles + role
  // (0: the gridpoint's own, 1: edge end a, 2: edge end b, 3 and 4: the far ends of the
  // gridpoint's edges), in a fixed order.
  std::vector<int> gather_first, gather;
  // Scratch of the cycle: per contact and role, the force (x, y) on that node, written by the
  // contact pass; the node pass adds push[2 * gather[s]] and the next, not reading the contact.
  std::vector<double> push;
  std::vector<double> rows;          // per node: Gershgorin row sum of contact stiffness [N/m^2]
  std::vector<double> x_detected;    // node positions when their blocks were last marked [m]
  bool detected = false;             // the list is current (materials, zones, positions)
  bool as_built = true;              // the next detection is the first on this mesh
  bool from_insitu = false;          // the next detection sets contact forces from insitu{}
  bool partial = false;              // some blocks were found again since the last full search
  // Its contacts' far ends and given states are known (false: read from a file without them,
  // until the next detection takes what they store as given and their far ends as found).
  bool facing_known = true;
  // Contacts found new but already pressed in by more than a tenth of their reach, since the
  // mesh was made: detection came too late for them (a lost contact); should stay 0.
  long late = 0;
  // Gridpoints whose contacts were searched for, since the mesh was made: what detection cost.
  long searched = 0;
  // Nodes a released tie made since the last detection, each with the node it split from (pairs:
  // new, old): its contacts on the faces the old node's no longer holds are those it takes over.
  std::vector<int> split_from;
};

// How far the gridpoint was inside the edge's block at the contact's last cycle (-gap) [m].
inline double last_overlap(const Contact& c) { return c.closure - c.closure0 - c.dilation; }

// A tip's carrying length from its own length and its tip's (wedge x overlap): the larger, its
// corner rounded over a band kTipBand x its own length wide each side, and the length's slopes
// with both. Taken sharp, the slope of what the springs store with the own length would jump where
// the tip's takes over: a shear stress kept as the own length changes stores tau^2 / (2 ks) a
// metre of it, paid by the push on the edges' far ends while the own length carries and by
// nothing once the tip's does, and a gridpoint rocking across that switch is pushed by a step
// that one sample a cycle integrates wrongly, energy made every crossing.
constexpr double kTipBand = 0.1;
struct TipLength {
  double length = 0.0, by_own = 0.0, by_tip = 0.0;  // [m], [-], [-]
};
inline TipLength tip_length(double own, double tip) {
  const double h = kTipBand * own, apart = own - tip;
  if (!(h > 0.0) || std::fabs(apart) >= h) return apart >= 0.0 ? TipLength{own, 1.0, 0.0} : TipLength{tip, 0.0, 1.0};
  const double r = h - std::fabs(apart), side = apart > 0.0 ? 1.0 : -1.0;
  TipLength t;
  t.length = std::max(own, tip) + r * r / (4.0 * h);
  t.by_tip = (apart < 0.0 ? 1.0 : 0.0) + r * side / (2.0 * h);
  // The band's width grows with the own length too.
  t.by_own = (apart > 0.0 ? 1.0 : 0.0) - r * side / (2.0 * h) + kTipBand * (h * h - apart * apart) / (4.0 * h * h);
  return t;
}

// A tip's length grows with its overlap up to its gridpoint's reach (Contact::limit) and no
// further: the depth it grows by, its overlap with that corner rounded over a band kReachBand x
// the reach wide each side, and the depth's slope with the overlap. Taken sharp, the slope of a
// tip's share with its depth (short of a sharp corner, contact_force) would stop at once at the
// reach, and with it part of its normal force: a gridpoint rocking across the reach is pushed by
// a step that one sample a cycle integrates wrongly, energy made every crossing.
constexpr double kReachBand = 0.1;
struct TipDepth {
  double depth = 0.0, slope = 0.0;  // [m], [-]
};
inline TipDepth tip_depth(double overlap, double limit) {
  if (!(overlap > 0.0)) return {};
  const double h = kReachBand * limit, into = overlap - (limit - h);
  if (!(into > 0.0)) return {overlap, 1.0};
  if (into >= 2.0 * h) return {limit, 0.0};
  return {overlap - into * into / (4.0 * h), 1.0 - into / (2.0 * h)};
}

// The overlap at which a tip has grown by `depth` (tip_depth's inverse) [m]; a depth not short of
// the reach: where the growth stops.
inline double overlap_at_tip_depth(double depth, double limit) {
  const double h = kReachBand * limit, into = depth - (limit - h);
  if (!(into > 0.0)) return depth;
  if (into >= h) return limit + h;
  return limit - h + 2.0 * (h - std::sqrt(h * (h - into)));
}

// The length that carries the contact's force at `overlap` [m] (before a corner's share): its
// own, or a tip's, which grows with the overlap up to its reach (tip_length, tip_depth).
inline double carrying_length(const Contact& c, double overlap) {
  return tip_length(c.length, c.wedge * tip_depth(overlap, c.limit).depth).length;
}

// The overlap from which a tip's length starts to outgrow its own (tip_length's band) [m].
inline double tip_takes_over(const Contact& c) {
  return c.wedge > 0.0 ? overlap_at_tip_depth(c.length * (1.0 - kTipBand) / c.wedge, c.limit) : INFINITY;
}

// The length that carried the contact's force at its last cycle [m], its corner's share taken.
// The overlap it is read at comes back from the closure, which holds the in-situ closure (some
// centimetres) beside it: an overlap below that sum's round-off is not known, and a tip whose
// length grows from nothing with it would read a length off by orders of magnitude, and through
// it a shear stress of ~1e19 Pa (a shear force rescaled by length_now / length_then). Such a tip
// carries no force worth keeping: it reads 0, and its shear spring starts afresh.
inline double last_carrying_length(const Contact& c) {
  const double overlap = last_overlap(c);
  if (c.wedge > 0.0) {  // a tip (a face's length does not hang on its overlap)
    const double round_off = 64.0 * std::numeric_limits<double>::epsilon() *
                             (std::fabs(c.closure) + std::fabs(c.closure0) + std::fabs(c.dilation));
    if (c.wedge * round_off > c.length && overlap <= round_off) return 0.0;
  }
  return c.share * carrying_length(c, overlap);
}

std::string_view to_string(ContactState state);

}  // namespace edem
