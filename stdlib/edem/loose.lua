-- edem.loose: blocks that have come loose (loose_blocks{}) and stay loose, for mucking out.
--
--   local loose = require "edem.loose"
--   local stays = loose.tracker()
--   every(200, function()
--     for _, b in ipairs(stays(function(block, before) return before end)) do excavate{ block = b.id } end
--   end)
--
-- loose.tracker() returns a function of `take(block, before)` that lists the blocks loose now
-- which `take` accepts, `before` telling whether the block was loose at the call before: a block
-- a transient lifts off its seat for a moment is loose at one check and not the next.
local loose = {}

function loose.tracker()
  local before = {}
  return function(take)
    local now, taken = {}, {}
    for b in loose_blocks{} do
      now[b.id] = true
      if take(b, before[b.id] == true) then taken[#taken + 1] = b end
    end
    before = now
    return taken
  end
end

return loose
