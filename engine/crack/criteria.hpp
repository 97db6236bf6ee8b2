// When a potential-crack section fails (the seed paper's §2.3, one sign corrected), from its
// in-plane principal stresses s1 <= s3 (compression negative: s1 the most compressive) and the
// rock's strength:
//   shear    f_s = (1 - sin phi) s1 - (1 + sin phi) s3 + 2 c cos phi,  fails when f_s < 0;
//   tension  f_t = sigma_t - s3,                                      fails when f_t < 0.
// (The seed prints "- 2 c cos phi" in f_s; with compression negative that cannot be right:
// uniaxial compression, s1 = -q and s3 = 0, must fail at q = UCS = 2 c cos phi / (1 - sin phi).)
// Where both fail, the section breaks in tension: the tensile stress opens it before any slip.
#pragma once

#include "constitutive/mohr_coulomb.hpp"

namespace edem {

double shear_function(const Principal& p, const RockStrength& rock);
double tension_function(const Principal& p, const RockStrength& rock);
CrackMode crack_mode(const Principal& p, const RockStrength& rock);
// How far past its strength the state is, as a ratio that is 1 on the failure envelope: the
// larger of s3 / sigma_t and the Mohr circle's radius over the shear strength at its centre,
// (s3 - s1) / 2 / (c cos phi - sin phi (s1 + s3) / 2). Ranks the sections that fail.
double overstress(const Principal& p, const RockStrength& rock);

}  // namespace edem
