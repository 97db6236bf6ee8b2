// The energy balance of a run (state/energy_ledger.hpp): what the model stores, starting the
// accounting, booking what commands and excavation change, the balance as energy() reports it.
#pragma once

#include "state/energy_ledger.hpp"

namespace edem {

struct Mechanics;

// What the model stores now: zones not null nor excavated, the nodes of such zones and the contacts
// between them, the bolts.
StoredEnergy stored_energy(const Mechanics& m);

// The kinetic energy of the rock's and the bolts' nodes with their cycling masses [J/m].
double kinetic_energy(const Mechanics& m);

// Starts the accounting afresh from the state now (the first cycle, energy{ reset = true }); the
// contacts' own books (ContactBook) start from nothing too.
void start_energy(Mechanics& m);

// Whether each contact keeps its own balance (energy{ by_contact = true }), from nothing now.
void book_by_contact(Mechanics& m, bool on);

// Books what commands changed since the ledger's last state (energy.last) as theirs, or
// (book_excavation) what changed since `before` as taken away by excavation, but for `booked`,
// what was booked meanwhile where it arose (a detection's prestress and rock dug out: the ledger's
// last state moved by it); the ledger's last state then follows the state now.
void book_commands(Mechanics& m);
void book_excavation(Mechanics& m, const StoredEnergy& before, const StoredEnergy& booked);

// The balance now. Between cycling commands (and in their callbacks), what commands changed since
// the ledger's last state counts as theirs.
EnergyReport energy_report(const Mechanics& m);

}  // namespace edem
