-- edem.kirsch: Kirsch's circular hole in an elastic plate under biaxial far-field stress
-- (Kirsch 1898; in Jaeger & Cook, Fundamentals of Rock Mechanics), for verification scripts.
--
--   local kirsch = require "edem.kirsch"
--   local hole = kirsch.new{ a = 1, p1 = 30e6, p2 = 15e6, shear = 2.8e9, bulk = 3.9e9 }
--   local sr, st, srt, ur = hole.at(r, theta)   -- compression positive, theta from the vertical
--   local worst, where = hole.worst_stress(1.2, 5)  -- zones with 1.2 a <= r <= 5 a: max error / p1
--
-- p1 acts vertically, p2 horizontally; plane strain (nu from bulk and shear). EDEM's stresses are
-- tension positive; worst_stress turns each zone's into polar components, compression positive.
local kirsch = {}

function kirsch.new(t)
  local a, p1, p2, G, K = t.a, t.p1, t.p2, t.shear, t.bulk
  local nu = (3 * K - 2 * G) / (2 * (3 * K + G))
  local hole = {}

  function hole.at(r, theta)
    local q = a * a / (r * r)
    local c2, s2 = math.cos(2 * theta), math.sin(2 * theta)
    local sr = (p1 + p2) / 2 * (1 - q) + (p1 - p2) / 2 * (1 - 4 * q + 3 * q * q) * c2
    local st = (p1 + p2) / 2 * (1 + q) - (p1 - p2) / 2 * (1 + 3 * q * q) * c2
    local srt = -(p1 - p2) / 2 * (1 + 2 * q - 3 * q * q) * s2
    local ur = (p1 + p2) / (4 * G) * a * a / r + (p1 - p2) / (4 * G) * a * a / r * (4 * (1 - nu) - q) * c2
    return sr, st, srt, ur
  end

  -- The largest error of any polar stress component at the centroids of the zones with
  -- from a <= r <= to a, over p1, and where it is.
  function hole.worst_stress(from, to)
    local worst, worst_at = 0, ""
    for z in zones() do
      local r = math.sqrt(z.x * z.x + z.y * z.y)
      if r >= from * a and r <= to * a and not z.excavated then
        local theta = math.atan(z.x, z.y)  -- from the vertical
        local sr, st, srt = hole.at(r, theta)
        -- e_r = (sin t, cos t), e_t = (cos t, -sin t)
        local c, s = math.sin(theta), math.cos(theta)
        local nsr = -(z.sxx * c * c + z.syy * s * s + 2 * z.sxy * s * c)
        local nst = -(z.sxx * s * s + z.syy * c * c - 2 * z.sxy * s * c)
        local nsrt = -((z.sxx - z.syy) * c * s + z.sxy * (s * s - c * c))
        for _, e in ipairs({ math.abs(nsr - sr), math.abs(nst - st), math.abs(nsrt - srt) }) do
          if e / p1 > worst then worst, worst_at = e / p1, ("r = %.2f, theta = %.0f"):format(r, math.deg(theta)) end
        end
      end
    end
    return worst, worst_at
  end

  return hole
end

return kirsch
