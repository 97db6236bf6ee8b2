// Zone law `elastic`: isotropic linear elasticity, plane strain. Its update is
// elastic_update (mohr_coulomb.hpp), which the cycle inlines: the entry has no update pointer.
#include "constitutive/zone_law.hpp"

namespace edem {

extern const ZoneLaw elastic_law;
const ZoneLaw elastic_law{
    .name = "elastic",
    .description = "linear elastic",
};

}  // namespace edem
