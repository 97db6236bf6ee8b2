// Model::field_frame: the model as it stands, for field output (io/field_output.hpp).
#include <cmath>
#include <optional>

#include "constitutive/zone_law.hpp"
#include "contact/detect.hpp"
#include "core/error.hpp"
#include "io/field_output.hpp"
#include "model/model.hpp"
#include "state/mechanics.hpp"

namespace edem {
namespace {

size_t at(int i) { return static_cast<size_t>(i); }

}  // namespace

FieldFrame Model::field_frame() const {
  const Mechanics& m = *mechanics_;
  FieldFrame f;
  f.time = m.info.time;
  f.cycle = m.info.cycle;
  f.stage = m.stage;
  if (mesh_.zone_count() == 0 || m.gp_node.empty()) return f;
  for (const MaterialDef& def : m.materials) f.material_names.push_back(def.name);
  // Where each solver node is measured from (origin + u is where it is now), and its displacement.
  const auto reference = [&](int node) {
    const size_t n = at(node);
    return Vec2{m.origin[2 * n], m.origin[2 * n + 1]};
  };
  const auto moved = [&](int node) {
    const size_t n = at(node);
    return std::array<double, 3>{m.u[2 * n], m.u[2 * n + 1], 0.0};
  };
  const auto now = [&](int node) { return reference(node) + Vec2{m.u[2 * at(node)], m.u[2 * at(node) + 1]}; };
  // The gridpoints of zones in place only, numbered as they are first met.
  std::vector<int> point_of(m.gp_node.size(), -1);
  for (int z = 0; z < mesh_.zone_count(); ++z) {
    const int material = m.zone_material[at(z)];
    const bool null = material < 0 || zone_law(m.params[at(material)].model).is_void;
    if (null || m.zone_excavated[at(z)] > 0) continue;
    const Stress& s = m.stress[at(z)];
    const Principal p = in_plane_principal(s);
    std::array<int, 3> corners{};
    for (size_t k = 0; k < 3; ++k) {
      const int gp = mesh_.zone_gp[at(z)][k];
      if (point_of[at(gp)] < 0) {
        const int node = m.gp_node[at(gp)];
        point_of[at(gp)] = static_cast<int>(f.points.size());
        f.points.push_back(reference(node));
        f.displacement.push_back(moved(node));
        f.velocity.push_back({m.v[2 * at(node)], m.v[2 * at(node) + 1], 0.0});
      }
      corners[k] = point_of[at(gp)];
    }
    f.triangles.push_back(corners);
    f.sxx.push_back(s.xx), f.syy.push_back(s.yy), f.sxy.push_back(s.xy), f.szz.push_back(s.zz);
    f.s1.push_back(p.s1), f.s3.push_back(p.s3);
    f.state.push_back(m.zone_state[at(z)]);
    f.material.push_back(material);
    f.block.push_back(mesh_.zone_block[at(z)]);
  }
  // Contacts as a detection now finds them; when the list is not current (before the first cycle,
  // or just after sections broke), found on a copy, so that a run with output goes on exactly as
  // one without.
  std::optional<ContactSet> fresh;
  if (!m.contacts.detected) {
    try {
      fresh = contacts_on_copy(m, mesh_);
    } catch (const Error&) {
      fresh = ContactSet{};  // not ready to cycle (a zone without material...): no contacts to show
    }
  }
  const ContactSet& found = fresh ? *fresh : m.contacts;
  // Each a line along the edge's direction through the gridpoint, of the contact's length.
  for (size_t id = 0; id < found.list.size(); ++id) {
    const Contact& c = found.list[id];
    const ContactEdge& e = m.faces.edges[at(c.edge)];
    const ContactView view = contact_view(m, found, static_cast<int>(id));
    const Vec2 d = now(e.b) - now(e.a);
    const Vec2 half = (0.5 * view.length / norm(d)) * d;
    // Moved back by its gridpoint's displacement: warped, the line is where the contact is now.
    const std::array<double, 3> u = moved(c.node);
    const Vec2 back = view.position - Vec2{u[0], u[1]};
    f.contact_points.push_back(back - half);
    f.contact_points.push_back(back + half);
    f.contact_displacement.push_back(u);
    f.contact_displacement.push_back(u);
    f.fn.push_back(view.fn), f.fs.push_back(view.fs), f.un.push_back(view.un), f.us.push_back(view.us);
    f.slip.push_back(view.slip);
    f.contact_state.push_back(static_cast<int>(c.state));
    f.contact_kind.push_back(view.kind == "crack" ? 1 : 0);
  }
  // Cracks: from the section's end A to its end B, on side 0.
  for (const CrackView& c : m.cracks) {
    const Section& s = m.sections[at(c.section)];
    for (const int gp : {s.a[0], s.b[0]}) {
      f.crack_points.push_back(reference(m.gp_node[at(gp)]));
      f.crack_displacement.push_back(moved(m.gp_node[at(gp)]));
    }
    f.crack_mode.push_back(static_cast<int>(c.mode));
    f.crack_cycle.push_back(static_cast<double>(c.cycle));
    f.crack_stage.push_back(c.stage);
  }
  const BoltSet& bolts = m.bolts;
  for (int b = 0; b < bolts.bolts(); ++b) {
    const bool removed = m.bolt_hosts.removed[at(b)] != 0;
    for (int s = bolts.bolt_first_segment[at(b)]; s < bolts.bolt_first_segment[at(b) + 1]; ++s) {
      const size_t i = at(s), a = at(bolts.segments.a[i]), e = at(bolts.segments.b[i]);
      for (const size_t node : {a, e}) {
        f.bolt_points.push_back(bolts.nodes.x[node]);
        f.bolt_displacement.push_back({bolts.nodes.u[node].x, bolts.nodes.u[node].y, 0.0});
      }
      f.bolt_force.push_back(bolts.segments.force[i]);
      f.bolt_strain.push_back(bolts.segments.elongation[i] / bolts.segments.rest[i]);
      f.bolt_state.push_back(removed ? 3 : static_cast<int>(bolts.segments.state[i]));
    }
  }
  return f;
}

}  // namespace edem
