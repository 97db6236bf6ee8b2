// A zone law: one constitutive model of the zones, as one entry of data (zone_laws.cpp lists
// them). The entry names the model, lists the keys it takes beyond the elastic constants (with
// units and ranges: the material{} schema and the reference are made from them), checks them and
// derives the kernel's constants (derive), updates a zone's stress by a strain increment
// (update; the implicit prepass takes its tangent from it: exact for elastic, central
// differences otherwise), names the per-zone state variable it keeps (history: saved in
// checkpoints, shown in zone views), and says what the rest of the engine asks of a model
// (is_void, has_strength, unsymmetric).
//
// A law's id is its position in the registry: MaterialDef::model and MaterialParams::model hold
// it (MaterialModel's enumerators name the first three). Id 0, elastic, is the cycle's inlined
// path; every other law's update is called through its entry's function pointer.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/physics_defs.hpp"
#include "state/material_params.hpp"
#include "state/stress.hpp"

namespace edem {

// A key a law takes: where its value goes in MaterialDef, its unit and range, one line of help.
struct ZoneLawParam {
  std::string_view key = {};
  std::string_view unit = {};  // SI unit, "-" for ratios
  double lo = 0.0, hi = 0.0;              // allowed range (numbers; each entry's value for tables)
  bool lo_open = false, hi_open = false;  // the bound itself excluded
  std::string_view help = {};             // what it is
  std::string_view note = {};             // appended after the laws that take it ("; capped at ...")
  std::string_view absent = {};           // what leaving it out means ("0")
  double MaterialDef::*number = nullptr;  // a number key: its field; nullptr: a table key
                                          // ({{abscissa, value}, ...}, in MaterialDef::tables)
};

// The points of table `key` in a definition; empty when not given.
const ZoneTable& law_table(const MaterialDef& def, std::string_view key);

// The stress update of one zone by a strain increment (dxx, dyy, engineering dxy, dzz), in
// place; `history` is the zone's own state variable (zone_history), which the law may advance.
// When the zone yields and `work` is not null, `*work` gets the step's plastic work per unit
// volume [J/m^3] (plastic_work, mohr_coulomb.hpp): the law has the elastic trial at hand, and
// the energy balance asks it of every yielding zone every cycle. Returns the zone state bits of
// the step (kShearNow, kTensionNow, or 0 when elastic).
using ZoneUpdate = std::uint8_t (*)(const MaterialParams& p, Stress& s, double dxx, double dyy, double dxy,
                                    double dzz, double& history, double* work);
// Checks the law's own keys of a definition whose elastic constants are already in `p`, and
// fills the rest of `p`. Throws edem::Error naming the key and the value.
using ZoneDerive = void (*)(const MaterialDef& def, MaterialParams& p);
// Whether the law's tangent is unsymmetric for these parameters (non-associated flow).
using ZoneUnsymmetric = bool (*)(const MaterialParams& p);

struct ZoneLaw {
  std::string_view name = {};
  std::string_view description = {};          // one phrase for the reference
  std::span<const ZoneLawParam> params = {};  // its keys beyond density and the elastic constants
  ZoneDerive derive = nullptr;           // nullptr: nothing beyond the elastic constants
  // nullptr: linear elastic (the cycle's inlined path, the prepass's exact tangent). Otherwise
  // the explicit kernel; the implicit prepass calls it too, with a copy of the history (the
  // zone's history does not advance inside a prepass), and takes its tangent by central
  // differences of it.
  ZoneUpdate update = nullptr;
  ZoneUnsymmetric unsymmetric = nullptr;  // nullptr: symmetric
  bool is_void = false;       // an empty zone (null): no stress, no mass, no elastic constants
  bool has_strength = false;  // cohesion, friction and tension judge cracks (crackseed{})
  // The name of the zone's state variable the law keeps in Mechanics::zone_history (saved in
  // checkpoints, shown in zone views under this name); empty: none.
  std::string_view history = {};
};

// The registry (zone_laws.cpp): every law, in id order.
std::span<const ZoneLaw* const> zone_laws();
// The registry's table, in id order (zone_laws.cpp); read it through zone_law().
extern const ZoneLaw* const kZoneLaws[];
// The law of an id; ids come from the registry, so they are always valid. Inline: the cycle asks
// it once per plastic zone update.
inline const ZoneLaw& zone_law(MaterialModel id) { return *kZoneLaws[static_cast<size_t>(id)]; }
// Sets `id` to the id of the law named `name`; false (id untouched) when no law has that name.
bool find_zone_law(std::string_view name, MaterialModel& id);
// The laws' names, in id order (material{ model } choices).
const std::vector<std::string>& zone_law_names();
// The names of the laws that take `key`, as `"mohr"` or `"mohr" or "ss"`.
std::string laws_taking(std::string_view key);

}  // namespace edem
