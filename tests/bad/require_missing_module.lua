-- line: 3
-- expect: lua: module 'edem.no_such_module' not found
local m = require "edem.no_such_module"
