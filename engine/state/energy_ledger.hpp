// The energy balance of a run, kept as PFC and 3DEC keep it: the work done on the model
// (gravity, boundary loads and moving supports, the loads an excavation takes off), the energy
// stored in it (kinetic, elastic in zones, contacts and bolts), what is dissipated (plastic work
// in zones, slip and bond failure on joints, damping, the bolts' yield and grout slip), and what
// commands between cycles change or excavation takes away. What is left over is the balance's
// error: energy the numerical method made or lost.
//
// Work and dissipation are summed every cycle, over the same steps the explicit scheme moves the
// nodes by: a force F found at cycle n does the work F . (u(n+1) - u(n-1)) / 2, the zones and
// contacts store and dissipate with the mid-step stress and force of each step. Stored energy is
// read off the state (stress, contact force, bolt force), so that an energy which appears without
// work (a contact's length changing under load, a contact made or dropped pressed in) shows as
// error, and the error is split by where it arises: the zones, the contacts, the bolts.
//
// All values are per metre of thickness [J/m], totals since the accounting started (the first
// cycle, or energy{ reset = true }); stored energies are their change since then.
#pragma once

namespace edem {

// Energy held in the state [J/m].
struct StoredEnergy {
  double kinetic = 0.0;  // 1/2 m v^2 of the rock's and the bolts' nodes, cycling masses
  double strain = 0.0;   // zones' elastic energy, 1/2 s : C^-1 : s area
  double normal = 0.0;   // contacts' normal springs, the integral of the normal force over closure
  double shear = 0.0;    // contacts' shear springs, fs^2 / (2 ks length)
  double bolt = 0.0;     // bolts' segments N^2 L / (2 EA) and grout F^2 / (2 k)
  double contact() const { return normal + shear; }
  double total() const { return kinetic + strain + normal + shear + bolt; }
};
inline StoredEnergy operator+(const StoredEnergy& a, const StoredEnergy& b) {
  return {a.kinetic + b.kinetic, a.strain + b.strain, a.normal + b.normal, a.shear + b.shear, a.bolt + b.bolt};
}
inline StoredEnergy operator-(const StoredEnergy& a, const StoredEnergy& b) {
  return {a.kinetic - b.kinetic, a.strain - b.strain, a.normal - b.normal, a.shear - b.shear, a.bolt - b.bolt};
}

// Running totals since the accounting started; part of the model's state (saved in checkpoints).
struct EnergyLedger {
  bool started = false;
  // Each contact keeps its own balance too (ContactSet::books; energy{ by_contact = true }). Not
  // kept in checkpoints.
  bool by_contact = false;
  StoredEnergy start;  // the state when it started
  // The state as booked at the last point where commands could act (a cycling command's end,
  // before its callbacks); `last_current` while nothing has cycled since.
  StoredEnergy last;
  bool last_current = false;
  // Work done on the model.
  double gravity = 0.0;   // by the weight of the rock
  double boundary = 0.0;  // by boundary loads, moving held gridpoints and bolt head drives
  double release = 0.0;   // by the loads an excavation takes off over cycles (excavate{ release })
  // Stored in contacts made with a given stress: insitu{}'s, or a broken section's traction.
  double prestress = 0.0;
  StoredEnergy commands;   // added by commands between cycles (insitu{}, reset{}, new properties)
  StoredEnergy excavated;  // taken away by excavate{} (dug out or mucked out)
  // Dissipated.
  double plastic = 0.0;       // in zones past their yield surface
  double slip = 0.0;          // by Coulomb slip of contacts
  double bond = 0.0;          // by bonds that soften or break (their elastic energy at the break)
  double damping = 0.0;       // by damping (static mode: also what the scaled masses change)
  double bolt_plastic = 0.0;  // by yielding and breaking bolt segments and slipping grout
  // Work done on the nodes by the forces of the contacts and of the bolts: the balance of each
  // part checks it (the zones' is what is left of the nodes' kinetic energy).
  double by_contacts = 0.0;  // contact forces on the rock's nodes
  double by_bolts = 0.0;     // grout on the rock's nodes, and segments and grout on the bolts' own
  // Of the contacts' energy made, what detections made (negative: lost) where a contact was found
  // on another face of the block its gridpoint presses into and started anew there: what it
  // stores then, beyond a stress it was given, less what it held on the old face; or where one
  // was dropped because its gridpoint, come round a corner of that block, is beside it (all it
  // held). A gridpoint pressed in about as deep as the block is thick is as near to another face.
  double restarted = 0.0;
};

// The balance as energy() reports it [J/m]; stored energies as changes since the start.
struct EnergyReport {
  StoredEnergy stored;  // change since the start
  double gravity = 0.0, boundary = 0.0, release = 0.0, prestress = 0.0, commands = 0.0;
  double excavated = 0.0;
  double plastic = 0.0, slip = 0.0, bond = 0.0, damping = 0.0, bolt_plastic = 0.0;
  // Energy the method made: what the model stores, dissipated and lost to excavation, less the
  // work done on it (negative: energy lost).
  double error = 0.0;
  // Where it arises: the contacts' and the bolts' stored and dissipated energy less the work done
  // on them; the zones' (with the nodes' integration) the rest. They add up to `error`.
  double zone_error = 0.0, contact_error = 0.0, bolt_error = 0.0;
  // Of contact_error, what contacts found on another face and started anew made (EnergyLedger).
  double restarted = 0.0;
  double largest = 0.0;  // the largest term, in magnitude
  double relative_error() const { return largest > 0.0 ? error / largest : 0.0; }
};

}  // namespace edem
