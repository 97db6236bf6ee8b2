// Zone law `null`: an empty zone, as excavated; no stress, no mass, no elastic constants.
#include "constitutive/zone_law.hpp"

namespace edem {

extern const ZoneLaw null_law;
const ZoneLaw null_law{
    .name = "null",
    .description = "an empty zone, as excavated",
    .is_void = true,
};

}  // namespace edem
