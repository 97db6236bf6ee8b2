// The energy balance: what the state stores, the ledger's bookings between cycles, the report.
#include "solver/energy.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "bolt/bolt_law.hpp"
#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/zone_law.hpp"
#include "contact/contact_force.hpp"
#include "state/mechanics.hpp"

namespace edem {

namespace {

// A zone that is rock: a material that is not null, not excavated.
bool rock_zone(const Mechanics& m, size_t z) {
  const int material = m.zone_material[z];
  return material >= 0 && !zone_law(m.params[static_cast<size_t>(material)].model).is_void &&
         m.zone_excavated[z] == 0;
}

double bolt_kinetic(const Mechanics& m) {
  const BoltHosts& h = m.bolt_hosts;
  double kinetic = 0.0;
  if (h.mass.size() != h.rate.size()) return kinetic;
  for (size_t i = 0; i < h.rate.size(); ++i) kinetic += 0.5 * h.mass[i] * h.rate[i] * h.rate[i];
  return kinetic;
}

}  // namespace

double kinetic_energy(const Mechanics& m) {
  double kinetic = bolt_kinetic(m);
  for (size_t n = 0; n < std::min(m.mass.size(), static_cast<size_t>(m.node_count)); ++n)
    kinetic += 0.5 * m.mass[n] * (m.v[2 * n] * m.v[2 * n] + m.v[2 * n + 1] * m.v[2 * n + 1]);
  return kinetic;
}

StoredEnergy stored_energy(const Mechanics& m) {
  StoredEnergy e;
  if (m.geometry.size() != m.zone_material.size()) return e;  // never prepared: nothing moves yet
  std::vector<char> live(static_cast<size_t>(m.node_count), 0);
  for (size_t z = 0; z < m.zone_material.size(); ++z) {
    if (!rock_zone(m, z)) continue;
    const ZoneGeometry& g = m.geometry[z];
    const MaterialParams& p = m.params[static_cast<size_t>(m.zone_material[z])];
    e.strain += 0.5 * g.area * compliance_product(p, m.stress[z], m.stress[z]);
    for (const int n : g.node) live[static_cast<size_t>(n)] = 1;
  }
  // (Nodes split off since the masses were found have none yet: their old node holds it.)
  for (size_t n = 0; n < std::min(live.size(), m.mass.size()); ++n)
    if (live[n]) e.kinetic += 0.5 * m.mass[n] * (m.v[2 * n] * m.v[2 * n] + m.v[2 * n + 1] * m.v[2 * n + 1]);
  e.kinetic += bolt_kinetic(m);
  // A contact is there while its gridpoint and its edge are on rock (a block dug out or mucked
  // out has nodes of its own: excavation unglues it from the rock in place).
  for (const Contact& c : m.contacts.list) {
    const ContactEdge& edge = m.faces.edges[static_cast<size_t>(c.edge)];
    if (!live[static_cast<size_t>(c.node)] || !live[static_cast<size_t>(edge.a)] || !live[static_cast<size_t>(edge.b)])
      continue;
    const ContactEnergy ce = contact_energy(c, m.joint_params[static_cast<size_t>(c.material)]);
    e.normal += ce.normal;
    e.shear += ce.shear;
  }
  e.bolt = bolt_energy(m.bolts);
  return e;
}

namespace {

// Each contact's book from nothing, with no force of a cycle before, as the ledger's work starts.
void clear_books(Mechanics& m) {
  m.contacts.books.assign(m.energy.by_contact ? m.contacts.list.size() : 0, ContactBook{});
}

}  // namespace

void book_by_contact(Mechanics& m, bool on) {
  m.energy.by_contact = on;
  clear_books(m);
}

void start_energy(Mechanics& m) {
  const bool by_contact = m.energy.by_contact;
  m.energy = EnergyLedger{};
  m.energy.by_contact = by_contact;
  clear_books(m);
  m.energy.started = true;
  m.energy.start = m.energy.last = stored_energy(m);
  m.energy.last_current = true;
}

void book_commands(Mechanics& m) {
  EnergyLedger& e = m.energy;
  const StoredEnergy now = stored_energy(m);
  e.commands = e.commands + (now - e.last);
  e.last = now;
  e.last_current = true;
}

void book_excavation(Mechanics& m, const StoredEnergy& before, const StoredEnergy& booked) {
  EnergyLedger& e = m.energy;
  if (!e.started) return;
  const StoredEnergy now = stored_energy(m);
  e.excavated = e.excavated + (before - now) + booked;
  e.last = e.last + (now - before) - booked;
}

EnergyReport energy_report(const Mechanics& m) {
  EnergyReport r;
  const EnergyLedger& e = m.energy;
  if (!e.started) return r;
  const StoredEnergy now = stored_energy(m);
  const StoredEnergy commands = e.last_current ? e.commands + (now - e.last) : e.commands;
  r.stored = now - e.start;
  r.gravity = e.gravity;
  r.boundary = e.boundary;
  r.release = e.release;
  r.prestress = e.prestress;
  r.commands = commands.total();
  r.excavated = e.excavated.total();
  r.plastic = e.plastic;
  r.slip = e.slip;
  r.bond = e.bond;
  r.damping = e.damping;
  r.bolt_plastic = e.bolt_plastic;
  const double in = r.gravity + r.boundary + r.release + r.prestress + r.commands;
  const double out = r.stored.total() + r.excavated + r.plastic + r.slip + r.bond + r.damping + r.bolt_plastic;
  r.error = out - in;
  // Each part's energy made: what it stored (beyond what commands gave it and excavation took)
  // and dissipated, less the work the nodes did on it (the negative of its forces' on them).
  const StoredEnergy own = r.stored - commands + e.excavated;
  r.contact_error = own.contact() + r.slip + r.bond - r.prestress + e.by_contacts;
  r.bolt_error = own.bolt + r.bolt_plastic + e.by_bolts;
  r.zone_error = r.error - r.contact_error - r.bolt_error;
  r.restarted = e.restarted;
  for (const double term : {r.stored.kinetic, r.stored.strain, r.stored.normal, r.stored.shear, r.stored.bolt,
                            r.gravity, r.boundary, r.release, r.prestress, r.commands, r.excavated, r.plastic,
                            r.slip, r.bond, r.damping, r.bolt_plastic})
    r.largest = std::max(r.largest, std::fabs(term));
  return r;
}

}  // namespace edem
