#include "crack/criteria.hpp"

#include <algorithm>
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

double overstress(const Principal& p, const RockStrength& rock) {
  const double phi = rock.friction * std::numbers::pi / 180.0;
  const double radius = 0.5 * (p.s3 - p.s1), centre = 0.5 * (p.s1 + p.s3);
  const double shear_strength = rock.cohesion * std::cos(phi) - std::sin(phi) * centre;
  const double shear = shear_strength > 0.0 ? radius / shear_strength : INFINITY;
  const double tension = rock.tension > 0.0 ? p.s3 / rock.tension : (p.s3 > 0.0 ? INFINITY : 0.0);
  return std::max(shear, tension);
}

}  // namespace edem
