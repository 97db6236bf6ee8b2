// Zone law `ss`: strain-softening Mohr-Coulomb, as FLAC's and UDEC's ss model. Cohesion, friction
// and dilation follow piecewise-linear tables against the zone's plastic shear strain e_ps (its
// zone_history); the tension cut-off is constant. Each step is Mohr-Coulomb's return mapping
// (mohr_coulomb.hpp) at the strength of the zone's e_ps at the start of the step, and a shear
// failure then advances e_ps by FLAC's measure of the step's plastic principal strains:
//   d e_ps = sqrt(0.5 [(d e1p - d emp)^2 + d emp^2 + (d e3p - d emp)^2]),  d emp = (d e1p + d e3p) / 3,
// with d e1p = lambda, d e3p = -lambda npsi from the shear flow rule. So, as in FLAC, the
// strength follows e_ps after each step. Beyond a table's last point its value stays.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "constitutive/material.hpp"
#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/zone_law.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr const char* kTableKeys[3] = {"cohesion_table", "friction_table", "dilation_table"};

// law_data: for cohesion, friction, dilation in turn, n then n abscissas then n values; then the
// tension as given (uncapped) [Pa].
double value_at(const double* table, double eps) {
  const size_t n = static_cast<size_t>(table[0]);
  const double* e = table + 1;
  const double* v = table + 1 + n;
  if (eps <= e[0]) return v[0];
  for (size_t i = 1; i < n; ++i)
    if (eps < e[i]) return v[i - 1] + (v[i] - v[i - 1]) * (eps - e[i - 1]) / (e[i] - e[i - 1]);
  return v[n - 1];
}

// Where table t (0 cohesion, 1 friction, 2 dilation) starts in law_data.
const double* table_of(const MaterialParams& p, int t) {
  const double* at = p.law_data.data();
  for (int i = 0; i < t; ++i) at += 1 + 2 * static_cast<size_t>(at[0]);
  return at;
}

MohrConstants strength_at(const MaterialParams& p, double eps) {
  return mohr_strength(p.e1, p.e2, value_at(table_of(p, 0), eps), value_at(table_of(p, 1), eps),
                       value_at(table_of(p, 2), eps), p.law_data.back());
}

// FLAC's plastic shear strain increment of a shear step of multiplier lambda.
double shear_strain_increment(double lambda, double npsi) {
  const double e1 = lambda, e3 = -lambda * npsi, em = (e1 + e3) / 3.0;
  return std::sqrt(0.5 * ((e1 - em) * (e1 - em) + em * em + (e3 - em) * (e3 - em)));
}

std::uint8_t update_ss(const MaterialParams& p, Stress& s, double dxx, double dyy, double dxy, double dzz,
                       double& eps, double* work) {
  const Stress before = s;
  elastic_update(p, s, dxx, dyy, dxy, dzz);
  const MohrConstants k = eps > 0.0 ? strength_at(p, eps) : mohr_constants(p);
  double lambda = 0.0;
  const std::uint8_t now = mohr_coulomb_return(k, s, &lambda, work ? &before : nullptr, work);
  if (now & kShearNow) eps += shear_strain_increment(lambda, k.npsi);
  return now;
}

// A table as given, checked: e_ps from 0, increasing; values in [lo, hi); its first value the
// number given for the peak. Empty when not given: the number then holds for every e_ps.
ZoneTable checked_table(const MaterialDef& def, int t, const char* number_key, double peak, double lo, double hi) {
  const char* key = kTableKeys[t];
  ZoneTable table = law_table(def, key);
  if (table.empty()) return {{0.0, peak}};
  for (size_t i = 0; i < table.size(); ++i) {
    const double e = table[i][0], v = table[i][1];
    if (!(e >= 0.0) || !std::isfinite(e)) fail("{} point {}: e_ps must be >= 0, got {}", key, i + 1, e);
    if (i == 0 && e != 0.0) fail("{} must start at e_ps = 0, got {}", key, e);
    if (i > 0 && !(e > table[i - 1][0]))
      fail("{} point {}: e_ps must increase, got {} after {}", key, i + 1, e, table[i - 1][0]);
    if (!(v >= lo && v < hi) || !std::isfinite(v)) {
      if (hi == kInf) fail("{} point {}: {} must be >= {}, got {}", key, i + 1, number_key, lo, v);
      fail("{} point {}: {} must be in [{}, {}), got {}", key, i + 1, number_key, lo, hi, v);
    }
  }
  if (table[0][1] != peak)
    fail("{} starts at {} (e_ps = 0), but {} is {}: give {} = {}, the peak value", key, table[0][1], number_key,
         peak, number_key, table[0][1]);
  return table;
}

void pack(const ZoneTable& table, std::vector<double>& out) {
  out.push_back(static_cast<double>(table.size()));
  for (const auto& point : table) out.push_back(point[0]);
  for (const auto& point : table) out.push_back(point[1]);
}

void derive_ss(const MaterialDef& def, MaterialParams& p) {
  const MaterialDef d = with_strength_defaults(def);
  if (!(std::isfinite(d.cohesion) && d.cohesion >= 0.0)) fail("cohesion must be >= 0, got {}", d.cohesion);
  if (!(d.friction >= 0.0 && d.friction < 90.0)) fail("friction must be in [0, 90), got {}", d.friction);
  if (!(d.dilation >= 0.0)) fail("dilation must be >= 0, got {}", d.dilation);
  if (!(std::isfinite(d.tension) && d.tension >= 0.0)) fail("tension must be >= 0, got {}", d.tension);
  const ZoneTable tables[3] = {checked_table(d, 0, "cohesion", d.cohesion, 0.0, kInf),
                               checked_table(d, 1, "friction", d.friction, 0.0, 90.0),
                               checked_table(d, 2, "dilation", d.dilation, 0.0, 90.0)};
  p.law_data.clear();
  for (const ZoneTable& table : tables) pack(table, p.law_data);
  p.law_data.push_back(d.tension);
  // Dilation at most friction everywhere: both are linear between their points, so at the points.
  for (const ZoneTable* table : {&tables[1], &tables[2]})
    for (const auto& point : *table) {
      const double phi = value_at(table_of(p, 1), point[0]), psi = value_at(table_of(p, 2), point[0]);
      if (psi > phi) fail("dilation must be <= friction at every e_ps: at e_ps = {}, {} > {}", point[0], psi, phi);
    }
  set_mohr_strength(p, d.cohesion, d.friction, d.dilation, d.tension);
}

// Symmetric only when dilation equals friction at every e_ps.
bool unsymmetric_ss(const MaterialParams& p) {
  const double* f = table_of(p, 1);
  const double* d = table_of(p, 2);
  return !std::equal(f, f + 1 + 2 * static_cast<size_t>(f[0]), d, d + 1 + 2 * static_cast<size_t>(d[0]));
}

const ZoneLawParam kParams[] = {
    {.key = "cohesion", .unit = "Pa", .lo = 0, .hi = kInf, .help = "cohesion", .absent = "0",
     .number = &MaterialDef::cohesion},
    {.key = "friction", .unit = "deg", .lo = 0, .hi = 90, .hi_open = true, .help = "friction angle",
     .absent = "0", .number = &MaterialDef::friction},
    {.key = "dilation", .unit = "deg", .lo = 0, .hi = kInf, .help = "dilation angle, at most friction",
     .absent = "0", .number = &MaterialDef::dilation},
    {.key = "tension", .unit = "Pa", .lo = 0, .hi = kInf, .help = "tensile strength", .absent = "0",
     .number = &MaterialDef::tension},
    {.key = "cohesion_table", .unit = "-, Pa", .help = "cohesion against the plastic shear strain e_ps: "
     "{{e_ps, cohesion}, ...} from e_ps = 0 (cohesion's value), e_ps increasing, constant after the last",
     .absent = "cohesion at every e_ps"},
    {.key = "friction_table", .unit = "-, deg", .help = "friction angle against e_ps, as cohesion_table",
     .absent = "friction at every e_ps"},
    {.key = "dilation_table", .unit = "-, deg", .help = "dilation angle against e_ps, as cohesion_table",
     .absent = "dilation at every e_ps"},
};

}  // namespace

extern const ZoneLaw strain_softening_law;
const ZoneLaw strain_softening_law{
    .name = "ss",
    .description = "strain-softening Mohr-Coulomb, as FLAC's ss: cohesion, friction and dilation "
                   "follow tables against the plastic shear strain e_ps",
    .params = kParams,
    .derive = derive_ss,
    .update = update_ss,
    .unsymmetric = unsymmetric_ss,
    .has_strength = true,
    .history = "e_ps",
};

}  // namespace edem
