// Building the contact boundary of a mesh, giving edges their joint materials, and finding the
// contacts (contacts.hpp).
#pragma once

#include "geom/mesh.hpp"
#include "state/mechanics.hpp"

namespace edem {

// The touchable boundary of every block, with solver nodes (m.gp_node must be set); edges
// flagged in edge_glued (per flat loop edge, state/sections.hpp) are not touchable.
ContactBoundary contact_boundary(const Mesh& mesh, const std::vector<char>& edge_glued,
                                 const std::vector<int>& gp_node,
                                 const std::vector<double>& position);

// Whether a jassign{} (its region resolved) selects an edge: touchable, of its kind and set,
// the midpoint inside its region.
bool jassign_selects(const JassignDef& rule, const Polygon& region, const ContactEdge& e,
                     const std::vector<double>& position);

// What made an edge, for messages: "a joint of set 2", "a crack", "a region outline", ...
std::string describe(const ContactEdge& e);

// The median length of the touchable edges, at the nodes' positions `position` [m] (0: none).
double median_edge_length(const ContactBoundary& cb, const std::vector<double>& position);
// Sets ContactEdge::glued_tip_a, glued_tip_b from the edges' glue and the reference positions
// (called by contact_boundary; a restored boundary has them set again the same way).
void mark_glued_tips(ContactBoundary& cb, const std::vector<double>& position);

// The overlap watchdog's limit [m]: set{ overlap }, or half the median touchable edge plus the
// largest closure a joint law follows its measured curve over (JointParams::curve_closure).
// A contact a gridpoint has is followed this deep, so that one pressed in this far is still
// found (new contacts are made within the gridpoint's reach).
double overlap_limit(const Mechanics& m);

// Gives every edge the joint material of the last jassign{} that selects it.
void assign_joint_materials(Mechanics& m);

// Finds the contacts at the current positions, carrying over the state of those that persist;
// rebuilds the force gather and the stiffness rows. Throws edem::Error, changing nothing, when
// a contact forms on an edge without a joint material.
void detect_contacts(Mechanics& m);

// Rebuilds set.gather_first and set.gather from its list: the forces each of the node_count
// nodes takes, by contact and role (kContactRoles), in contact order.
void gather_contact_forces(ContactSet& set, const ContactBoundary& cb, int node_count);

// The contacts a detection would find now, found on a copy of m: m is left as it is (a view from
// a callback or a field-output frame must not change the run). Throws edem::Error as prepare()
// and detect_contacts() do (model_contacts.cpp).
ContactSet contacts_on_copy(const Mechanics& m, const Mesh& mesh);

// Contact `id` of `set` (m.contacts, or one found on a copy of m) as contacts() shows it
// (model_contacts.cpp).
ContactView contact_view(const Mechanics& m, const ContactSet& set, int id);

// Finds the contacts again where they may have changed: all of them when none are current;
// else, once some block has moved a quarter of the smallest reach since the last full search
// (an eighth after a partial one), those of every block whose boundary has moved an eighth of
// it since it was last marked (allowing twice its nodes' speed over `ahead` cycles more), and
// of the blocks near those, keeping the rest. A node's contacts were found no more than half the
// smallest reach of relative motion ago, as when everything is found again at a quarter of it.
// Returns whether any were found again (the masses then need updating).
bool refresh_contacts(Mechanics& m, double ahead);

}  // namespace edem
