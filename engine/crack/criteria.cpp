#include "crack/criteria.hpp"

#include <cmath>
#include <numbers>

namespace edem {

double shear_function(const Principal& p, const RockStrength& rock) {
  const double phi = rock.friction * std::numbers::pi / 180.0;
  const double sin_phi = std::sin(phi);
  return (1.0 - sin_phi) * p.s1 - (1.0 + sin_phi) * p.s3 + 2.0 * rock.cohesion * std::cos(phi);
}

double tension_function(const Principal& p, const RockStrength& rock) {
  return rock.tension - p.s3;
}

CrackMode crack_mode(const Principal& p, const RockStrength& rock) {
  if (tension_function(p, rock) < 0.0) return CrackMode::tension;
  if (shear_function(p, rock) < 0.0) return CrackMode::shear;
  return CrackMode::none;
}

}  // namespace edem
