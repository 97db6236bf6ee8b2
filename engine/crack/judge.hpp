// Judging potential-crack sections (seed paper §2.3-2.4): the stress at each intact section's
// calculation point (section_stress.hpp), the criteria (criteria.hpp) or a user's, and breaking the
// sections that fail.
#pragma once

#include "geom/mesh.hpp"
#include "state/mechanics.hpp"

namespace edem {

// Derives m.fits from the active zones, materials and jassign{} rules (in prepare()). Throws
// edem::Error, naming the crackseed{}, when a section has no strength (its rock material is
// not Mohr-Coulomb) or its cracks would have no joint material.
void fit_sections(Mechanics& m, const Mesh& mesh);

// The section as a criterion sees it, with the fitted stress of now.
SectionView section_view(const Mechanics& m, int section);

// Judges every intact section whose zones are active, all against the same state, then breaks
// those that fail (crack records, ties released): with judge{ neighbours = "wait" } only the
// worst of those that touch, with judge{ most } at most that many. Returns how many broke: the
// caller then reconnects the nodes across them (solver/prepare.hpp, reconnect).
// Exceptions from a user's criterion pass through, with nothing broken.
int judge_sections(Mechanics& m);

}  // namespace edem
