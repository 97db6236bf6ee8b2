-- Speed against accuracy for the choices a user makes on the seed's cavern: judging mode,
-- release, damping and zone size near the opening. Reads the tables
-- tests/bench/judging_independence.sh writes and draws two charts, run time against the change in
-- crack count and against the change in crown settlement, each relative to the most careful run of
-- its kind:
--   - judging mode, damping and release: against judged at equilibrium, local damping, the load
--     released over 10,000 cycles (1.5 m zones);
--   - zone size near the opening (judged at equilibrium, local damping, released over 100
--     cycles): against the finest zones.
-- A change of zero is drawn at 0.1 %, the chart's floor, so that it shows on log axes. Each line
-- joins a kind of run's points in order of run time; the printed table says which point is which.
--   edem --set summary=OUT/summary.csv --set zones=OUT/zones.csv --set out=DIR run tests/bench/judging_chart.lua
local summary_file = assert(arg and arg.summary, "--set summary=FILE: judging_independence.sh's summary.csv")
local zones_file = assert(arg.zones, "--set zones=FILE: judging_independence.sh's zones.csv")
local out = arg.out or "."
local FLOOR = 1e-3

local function read_csv(file)
  local rows, header = {}, nil
  for line in io.lines(file) do
    local cells = {}
    for cell in line:gmatch("[^,]+") do cells[#cells + 1] = cell end
    if not header then
      header = cells
    else
      local row = {}
      for i, name in ipairs(header) do row[name] = tonumber(cells[i]) or cells[i] end
      rows[#rows + 1] = row
    end
  end
  return rows
end

local function change(value, reference) return math.max(FLOOR, math.abs(value - reference) / reference) end

local runs, zones = read_csv(summary_file), read_csv(zones_file)
local reference
for _, r in ipairs(runs) do
  if r.judge == "equilibrium" and r.damping == "local" and r.release == 10000 then reference = r end
end
assert(reference, "no run judged at equilibrium, local damping, released over 10,000 cycles in " .. summary_file)
local finest = zones[1]
for _, z in ipairs(zones) do if z.edge < finest.edge then finest = z end end

local cracks_series, crown_series = {}, {}
-- A series a kind of run, its points in order of run time.
local function add(name, rows, ref)
  local cracks, crown = { name = name, x = {}, y = {} }, { name = name, x = {}, y = {} }
  local by_time = { table.unpack(rows) }
  table.sort(by_time, function(a, b) return a.seconds < b.seconds end)
  for _, r in ipairs(by_time) do
    table.insert(cracks.x, r.seconds); table.insert(cracks.y, change(r.cracks, ref.cracks))
    table.insert(crown.x, r.seconds); table.insert(crown.y, change(r.crown_m, ref.crown_m))
  end
  cracks_series[#cracks_series + 1], crown_series[#crown_series + 1] = cracks, crown
end
print(("reference: judged at equilibrium, local damping, release 10000: %d cracks, crown %.4f m, %d s"):format(
  reference.cracks, reference.crown_m, reference.seconds))
for _, judge in ipairs({ "equilibrium", "cycles" }) do
  for _, damping in ipairs({ "local", "adaptive" }) do
    local rows = {}
    for _, r in ipairs(runs) do
      if r.judge == judge and r.damping == damping and r.release ~= 20000 then rows[#rows + 1] = r end
    end
    table.sort(rows, function(a, b) return a.release < b.release end)
    local label = ("%s, %s damping, release 1 / 100 / 10000"):format(
      judge == "equilibrium" and "at equilibrium" or "every 10 cycles", damping)
    for _, r in ipairs(rows) do
      print(("  %-55s release %5d: %4d s, cracks %3d (%.1f %%), crown %.4f m (%.2f %%)"):format(label, r.release,
        r.seconds, r.cracks, 100 * math.abs(r.cracks - reference.cracks) / reference.cracks, r.crown_m,
        100 * math.abs(r.crown_m - reference.crown_m) / reference.crown_m))
    end
    add(label, rows, reference)
  end
end
for _, r in ipairs(runs) do
  if r.release == 20000 then add("every 10 cycles, local, release 20000 (the seed's way)", { r }, reference) end
end
table.sort(zones, function(a, b) return a.edge > b.edge end)
for _, z in ipairs(zones) do
  print(("  zones of %.1f m at the opening (at equilibrium, local, release 100): %4d s, cracks %3d (%.1f %% from "
         .. "the finest), crown %.4f m (%.2f %%)"):format(z.edge, z.seconds, z.cracks,
         100 * math.abs(z.cracks - finest.cracks) / finest.cracks, z.crown_m,
         100 * math.abs(z.crown_m - finest.crown_m) / finest.crown_m))
end
add("zones of 2 / 1.5 / 1 m at the opening, against 1 m", zones, finest)

chart{ file = out .. "/judging_cracks.png", title = "Seed cavern, Case 3, Set P: crack count against run time",
       x_label = "run time [s, one core]", y_label = "change in crack count (0 drawn at 0.1 %)",
       log = { "x", "y" }, series = cracks_series }
chart{ file = out .. "/judging_crown.png", title = "Seed cavern, Case 3, Set P: crown settlement against run time",
       x_label = "run time [s, one core]", y_label = "change in crown settlement (0 drawn at 0.1 %)",
       log = { "x", "y" }, series = crown_series }
print(("wrote %s/judging_cracks.png and %s/judging_crown.png"):format(out, out))
