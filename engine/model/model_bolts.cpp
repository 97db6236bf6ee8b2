// The Model's bolt commands: bolt materials, bolts laid in the rock, their heads, their views.
#include <algorithm>
#include <cmath>

#include "bolt/bolt_coupling.hpp"
#include "bolt/bolt_law.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "model/model.hpp"
#include "state/mechanics.hpp"

namespace edem {
namespace {

size_t at(int i) { return static_cast<size_t>(i); }

BoltParams params_of(const BoltMaterialDef& def) {
  BoltParams p;
  p.young = def.young;
  p.area = def.area;
  p.density = def.density;
  p.yield_tension = def.yield_tension;
  p.yield_compression = std::isnan(def.yield_compression) ? def.yield_tension : def.yield_compression;
  p.failure_strain = def.failure_strain;
  p.bond_stiffness = def.bond_stiffness;
  p.bond_strength = def.bond_strength;
  p.spacing = def.spacing;
  return p;
}

const char* segment_state(SegmentState state) {
  switch (state) {
    case SegmentState::yielded: return "yielded";
    case SegmentState::broken: return "broken";
    case SegmentState::removed: return "removed";
    case SegmentState::elastic: break;
  }
  return "elastic";
}

// The grout's whole slip at a bolt node: elastic (force / stiffness) and plastic [m].
double grout_slip(const BoltNodes& n, size_t i) {
  const double elastic = n.grout_stiffness[i] > 0.0 ? n.grout_force[i] / n.grout_stiffness[i] : 0.0;
  return elastic + n.grout_slip[i];
}

void check_point(Vec2 p, const char* key) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail("{} must be a finite point, got ({}, {})", key, p.x, p.y);
}

}  // namespace

void Model::add_bolt_material(const BoltMaterialDef& def) {
  Mechanics& m = *mechanics_;
  if (def.name.empty()) fail("a bolt material needs a name");
  const BoltLaw law = bolt_law(params_of(def));  // checks every value
  for (size_t i = 0; i < m.bolt_materials.size(); ++i) {
    if (m.bolt_materials[i].name != def.name) continue;
    if (std::find(m.bolt_hosts.material.begin(), m.bolt_hosts.material.end(), static_cast<int>(i)) !=
        m.bolt_hosts.material.end())
      fail("bolt material '{}' is used by bolts already: give the new values another name", def.name);
    m.bolt_materials[i] = def;
    m.bolts.laws[i] = law;
    return;
  }
  m.bolt_materials.push_back(def);
  m.bolts.laws.push_back(law);
}

std::vector<std::string> Model::bolt_material_names() const {
  std::vector<std::string> names;
  for (const auto& material : mechanics_->bolt_materials) names.push_back(material.name);
  return names;
}

int Model::add_bolt(const BoltDef& def) {
  Mechanics& m = *mechanics_;
  const int material = index_of_name(m.bolt_materials, def.material, "bolt material", "bolt_material{...}");
  if (mesh_.zone_count() == 0) fail("there are no zones to hold a bolt: zone{{...}} the blocks first");
  check_point(def.from, "from");
  check_point(def.to, "to");
  const double length = norm(def.to - def.from);
  if (!(length > 0.0)) fail("from and to are the same point ({}, {}): a bolt needs a length", def.from.x, def.from.y);
  if (!(def.free_length >= 0.0 && def.free_length < length))
    fail("free_length must be in [0, {:.6g}) m (the bolt's length), got {}", length, def.free_length);
  const bool by_count = def.segments != 0, by_length = !std::isnan(def.segment_length);
  if (by_count == by_length) fail("give segments = n or segment_length = l (one of them)");
  int segments = def.segments;
  if (by_count && segments < 1) fail("segments must be at least 1, got {}", segments);
  if (by_length) {
    if (!(def.segment_length > 0.0 && std::isfinite(def.segment_length)))
      fail("segment_length must be a finite length > 0 [m], got {}", def.segment_length);
    segments = std::max(1, static_cast<int>(std::ceil((length - def.free_length) / def.segment_length - 1e-9)));
  }
  for (const int z : m.zone_material)
    if (z < 0) fail("zones without material: assign{{}} the rock before laying bolts in it");
  BoltLine line;
  line.head = def.from;
  line.end = def.to;
  line.segments = segments;
  line.free_length = def.free_length;
  const int bolt = install_bolt(m, line, material);
  if (!cycling_started() && !m.replaying) m.replay.push_back([def](Model& model) { model.add_bolt(def); });
  return bolt;
}

void Model::bolt_head(const BoltHeadDef& def) {
  Mechanics& m = *mechanics_;
  if (def.bolt < 0 || def.bolt >= m.bolts.bolts())
    fail("there is no bolt {} ({} laid so far)", def.bolt + 1, m.bolts.bolts());
  const bool velocity = !std::isnan(def.velocity), force = !std::isnan(def.force);
  if (velocity && force) fail("give velocity = v or force = f, not both");
  if ((velocity && !std::isfinite(def.velocity)) || (force && !std::isfinite(def.force)))
    fail("the head's velocity or force must be finite");
  BoltHosts& h = m.bolt_hosts;
  const size_t b = at(def.bolt);
  if ((velocity || force) && !head_on_bolt(m, def.bolt))
    fail("bolt {}'s head was cut off with its rock (excavated): there is no head to drive",
         def.bolt + 1);
  h.drive[b] = velocity ? HeadDrive::velocity : force ? HeadDrive::force : HeadDrive::none;
  const double spacing = m.bolt_materials[at(h.material[b])].spacing;
  h.drive_value[b] = velocity ? def.velocity : force ? def.force / spacing : 0.0;
  m.dirty = true;  // the head's node is held or free: masses and damping start again
  if (!cycling_started() && !m.replaying) m.replay.push_back([def](Model& model) { model.bolt_head(def); });
}

int Model::bolt_count() const { return mechanics_->bolts.bolts(); }

BoltView Model::bolt(int id) const {
  const Mechanics& m = *mechanics_;
  if (id < 0 || id >= m.bolts.bolts()) fail("there is no bolt {} ({} laid so far)", id + 1, m.bolts.bolts());
  const BoltSet& set = m.bolts;
  const BoltHosts& h = m.bolt_hosts;
  const BoltNodes& n = set.nodes;
  const size_t b = at(id);
  BoltView view;
  view.id = id;
  view.material = m.bolt_materials[at(h.material[b])].name;
  view.stage = h.stage[b];
  const int first = set.bolt_first_node[b], last = set.bolt_first_node[b + 1] - 1;
  view.head = n.x[at(first)];
  view.end = n.x[at(last)];
  view.length = norm(view.end - view.head);
  view.head_force = h.head_force[b];
  view.removed = h.removed[b] != 0;
  for (int s = set.bolt_first_segment[b]; s < set.bolt_first_segment[b + 1]; ++s) {
    const size_t i = at(s), a = at(set.segments.a[i]), e = at(set.segments.b[i]);
    BoltSegmentView seg;
    seg.a = n.x[a] + n.u[a];
    seg.b = n.x[e] + n.u[e];
    seg.force = set.segments.force[i];
    seg.strain = set.segments.elongation[i] / set.segments.rest[i];
    seg.slip = 0.5 * (grout_slip(n, a) + grout_slip(n, e));
    seg.plastic_slip = 0.5 * (n.grout_slip[a] + n.grout_slip[e]);
    seg.state = view.removed ? "removed" : segment_state(set.segments.state[i]);
    seg.broke = set.segments.broke[i] != 0;
    view.segments.push_back(seg);
  }
  return view;
}

}  // namespace edem
