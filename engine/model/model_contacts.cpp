// The Model's joint commands and contact views: joint_material{}, jassign{}, contacts().
#include <algorithm>
#include <cmath>

#include "contact/detect.hpp"
#include "contact/joint_law.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "model/model.hpp"
#include "solver/prepare.hpp"
#include "state/mechanics.hpp"

namespace edem {
namespace {

// Contacts are found when cycling starts; a view before that finds them now.
void ensure_contacts(Mechanics& m, const Mesh& mesh) {
  if (m.contacts.detected) return;
  prepare(m, mesh);
  detect_contacts(m);
  update_masses(m);
}

// The contacts a view shows: the model's, found now if they are not current. From a callback
// while cycling they are found on a copy instead, once a cycle: finding them on the model would
// prepare it and find them out of turn, and the run would go on differently for having been
// looked at.
const ContactSet& view_contacts(Mechanics& m, const Mesh& mesh) {
  if (m.contacts.detected) return m.contacts;
  if (!m.cycling_now) {
    ensure_contacts(m, mesh);
    return m.contacts;
  }
  if (m.viewed_cycle != m.info.cycle) {
    m.viewed_contacts = contacts_on_copy(m, mesh);
    m.viewed_cycle = m.info.cycle;
  }
  return m.viewed_contacts;
}

}  // namespace

ContactSet contacts_on_copy(const Mechanics& m, const Mesh& mesh) {
  Mechanics copy = m;
  prepare(copy, mesh);
  detect_contacts(copy);
  return std::move(copy.contacts);
}

void Model::add_joint_material(const JointMaterialDef& def) {
  const JointParams params = joint_params(def);
  Mechanics& m = *mechanics_;
  for (size_t i = 0; i < m.joint_materials.size(); ++i) {
    if (m.joint_materials[i].name != def.name) continue;
    m.joint_materials[i] = def;
    m.joint_params[i] = params;
    m.dirty = true;  // the step allows for the stiffest law
    return;
  }
  m.joint_materials.push_back(def);
  m.joint_params.push_back(params);
}

std::vector<std::string> Model::joint_material_names() const {
  std::vector<std::string> names;
  for (const auto& material : mechanics_->joint_materials) names.push_back(material.name);
  return names;
}

void Model::jassign(const JassignDef& def) {
  Mechanics& m = *mechanics_;
  const int material = index_of_name(m.joint_materials, def.material, "joint material", "joint_material{...}");
  if (mesh_.zone_count() == 0) fail("there are no contacts to assign to: zone{{...}} the blocks first");
  if (!def.kind.empty() && def.kind != "joint" && def.kind != "crack") {
    if (def.kind == "glued")
      fail("glued edges (region outlines) join their blocks into one continuum and have no "
           "contacts; cut the region with glued = false to make its outline a joint");
    fail("kind must be \"joint\" or \"crack\", got \"{}\"", def.kind);
  }
  if (def.set >= joint_set_count())
    fail("set {} does not exist: the model has {} joint set{}", def.set + 1, joint_set_count(),
         joint_set_count() == 1 ? "" : "s");
  Polygon region;
  if (!def.region.empty()) region = resolve(def.region);
  // Something must be selected, or the assignment is surely a mistake.
  const bool any = std::any_of(m.faces.edges.begin(), m.faces.edges.end(),
                               [&](const ContactEdge& e) { return jassign_selects(def, region, e, m.position); });
  if (!any) fail("no joint or block edge that can touch another matches this jassign{{}}");
  m.jassign.push_back(def);
  m.jassign_regions.push_back(region);
  m.jassign_material.push_back(material);
  m.dirty = true;
  if (!cycling_started() && !m.replaying)
    m.replay.push_back([def](Model& model) { model.jassign(def); });
}

int Model::contact_count() const {
  return static_cast<int>(view_contacts(*mechanics_, mesh_).list.size());
}

int Model::contacts_now() const {
  const Mechanics& m = *mechanics_;
  if (m.contacts.detected) return static_cast<int>(m.contacts.list.size());
  if (m.cycling_now) return contact_count();  // a copy's, once a cycle
  return static_cast<int>(contacts_on_copy(m, mesh_).list.size());
}

ContactView Model::contact(int id) const {
  const ContactSet& set = view_contacts(*mechanics_, mesh_);
  if (id < 0 || id >= static_cast<int>(set.list.size())) fail("no contact {}", id + 1);
  return contact_view(*mechanics_, set, id);
}

ContactView contact_view(const Mechanics& m, const ContactSet& set, int id) {
  const Contact& c = set.list[static_cast<size_t>(id)];
  const ContactEdge& e = m.faces.edges[static_cast<size_t>(c.edge)];
  auto at = [&](int node) {
    const size_t n = static_cast<size_t>(node);
    return Vec2{m.origin[2 * n] + m.u[2 * n], m.origin[2 * n + 1] + m.u[2 * n + 1]};
  };
  ContactView view;
  view.id = id;
  view.position = at(c.node);
  const Vec2 d = at(e.b) - at(e.a);
  view.normal = {d.y / norm(d), -d.x / norm(d)};
  // What carries its force now (the overlap as its last cycle left it).
  view.length = c.share * carrying_length(c, last_overlap(c));
  const bool open = c.state == ContactState::open;
  view.fn = open ? 0.0 : -c.sn * view.length;
  view.fs = c.fs;
  view.un = c.dilation - c.closure;  // the faces' opening: dilation opens them at a given stress
  view.overlap = last_overlap(c);
  view.us = c.us;
  view.slip = c.slip;
  view.state = std::string(to_string(c.state));
  view.kind = e.origin.kind == EdgeKind::crack ? "crack" : "joint";
  view.material = m.joint_materials[static_cast<size_t>(c.material)].name;
  view.block = c.block;
  view.other = c.other;
  view.corner = c.split;
  view.face = c.face;
  if (m.energy.by_contact && id < static_cast<int>(set.books.size())) {
    // With the work of its last force over the half step the nodes have moved since, as the
    // balance has booked it.
    const ContactBook& book = set.books[static_cast<size_t>(id)];
    view.energy_made = book.made + half_step_work(book, m.v.data(), m.step);
  }
  for (double value : {view.fn, view.fs, view.un, view.us})
    if (!std::isfinite(value)) fail("contact {} holds no finite force: the run went unstable earlier", id + 1);
  return view;
}

int Model::contact_near(Vec2 point) const {
  const ContactSet& set = view_contacts(*mechanics_, mesh_);
  const Mechanics& m = *mechanics_;
  int best = -1;
  double best_distance = INFINITY;
  for (size_t i = 0; i < set.list.size(); ++i) {
    const size_t n = static_cast<size_t>(set.list[i].node);
    const double dx = m.origin[2 * n] + m.u[2 * n] - point.x, dy = m.origin[2 * n + 1] + m.u[2 * n + 1] - point.y;
    const double d = dx * dx + dy * dy;
    if (d < best_distance) best_distance = d, best = static_cast<int>(i);
  }
  return best;
}

}  // namespace edem
