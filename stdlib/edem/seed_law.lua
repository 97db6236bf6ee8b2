-- edem.seed_law: the seed paper's joint law as a closed form, for verification scripts: its lab
-- cubic sn = -4.302 v^3 + 7.688 v^2 - 0.123 v (MPa, v in mm; Jiang et al., eq. 7) from its zero
-- crossing v0, straight at 1880 MPa/m past its descending 1880 MPa/m point v1, and scaled by
-- similarity (stresses x S, closures x L). Written here from the paper, not from the engine's
-- joint law, so that the scripts check one against the other.
--
--   local law = require "edem.seed_law"
--   law.stress(c, S, L)     -- closure c [m] -> sn [Pa], compression positive (S, L default 1)
--   law.closure(sn, S, L)   -- its inverse, by bisection
--   law.poly(v), law.slope(v), law.v0, law.v1   -- the cubic [MPa], its tangent [MPa/mm]; mm
local law = {}

function law.poly(v) return ((-4.302 * v + 7.688) * v - 0.123) * v end
function law.slope(v) return (3 * -4.302 * v + 2 * 7.688) * v - 0.123 end
law.v0 = (-7.688 + math.sqrt(7.688 ^ 2 - 4 * -4.302 * -0.123)) / (2 * -4.302)
law.v1 = (-(2 * 7.688) - math.sqrt((2 * 7.688) ^ 2 - 4 * (3 * -4.302) * (-0.123 - 1.880))) / (2 * 3 * -4.302)

function law.stress(c, S, L)
  S, L = S or 1, L or 1
  local v = c / L * 1e3 + law.v0
  if v <= law.v1 then return S * law.poly(v) * 1e6 end
  return S * (law.poly(law.v1) * 1e6 + 1880e6 * (v - law.v1) * 1e-3)
end

-- On [0, 10 mm x L] (past the curve's reach at any stress the scripts load to), to machine precision.
function law.closure(sn, S, L)
  local lo, hi = 0, 0.01 * (L or 1)
  for _ = 1, 200 do
    local mid = 0.5 * (lo + hi)
    if law.stress(mid, S, L) < sn then lo = mid else hi = mid end
  end
  return 0.5 * (lo + hi)
end

return law
