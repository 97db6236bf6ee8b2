// Reading the model from a script: info(), energy(), gp_near(), zone_at() and the iterators
// blocks(), zones() and gridpoints().
//
// energy() reads the energy balance (solver/energy.hpp).
//
// Iterators hold only a position and look the model up at each step, so a script that changes
// the model inside the loop sees the new model, never a dangling reference. Ids are 1-based.
#include <fmt/format.h>

#include <cmath>
#include <string_view>
#include <lua.hpp>

#include "adaptor.hpp"
#include "commands.hpp"
#include "context.hpp"
#include "geom/polygon.hpp"
#include "iterator.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

// info().contacts: the contacts there are now, as contacts() counts them (a judgment or an
// excavation leaves them to be found again at the next cycle; "as last found" would read 0
// meanwhile). Counting stale ones means finding them on a copy of the model, so it is done only
// when a script reads the field, not at every info().
int count_contacts_when_read(lua_State* L) {
  const char* key = lua_tostring(L, 2);
  if (key == nullptr || std::string_view(key) != "contacts") return 0;
  lua_pushinteger(L, context_of(L).model().contacts_now());
  return 1;
}

// Lua's next(), whatever a script has made of the global of that name.
int next_field(lua_State* L) {
  lua_settop(L, 2);
  if (lua_next(L, 1) != 0) return 2;
  lua_pushnil(L);
  return 1;
}

// pairs(info()) lists contacts too: the count is taken once, as the iteration starts.
int pairs_with_contacts(lua_State* L) {
  lua_pushinteger(L, context_of(L).model().contacts_now());
  lua_setfield(L, 1, "contacts");  // a plain field now; __index is not asked again
  lua_pushcfunction(L, next_field);
  lua_pushvalue(L, 1);
  lua_pushnil(L);
  return 3;
}

int run_info(lua_State* L, Context& context, const Args&) {
  Model& model = context.model();
  const ModelInfo info = model.info();
  const SolverInfo solver = model.solver_info();
  lua_createtable(L, 0, 20);
  set_field(L, "blocks", info.blocks);
  set_field(L, "zones", info.zones);
  set_field(L, "gridpoints", info.gridpoints);
  set_field(L, "joint_edges", info.joint_edges);
  set_field(L, "dropped_cuts", info.dropped_cuts);
  set_field(L, "cuts_left_out", info.cuts_left_out);
  set_field(L, "cuts_cut_back", info.cuts_cut_back);
  set_field(L, "snapped", info.snapped);
  set_field(L, "slivers_kept", info.slivers_kept);
  set_field(L, "shortest_edge", info.shortest_edge);
  set_field(L, "regions", info.regions);
  set_field(L, "joint_sets", info.joint_sets);
  set_field(L, "crack_seeds", info.crack_seeds);
  set_field(L, "sections", info.sections);
  set_field(L, "intact_sections", info.intact_sections);
  set_field(L, "cracks", info.cracks);
  set_field(L, "shear_cracks", info.shear_cracks);
  set_field(L, "tension_cracks", info.tension_cracks);
  set_field(L, "stage", info.stage);
  set_field(L, "title", model.title());
  set_field(L, "cycle", static_cast<long long>(solver.cycle));
  set_field(L, "time", solver.time);
  set_field(L, "step", solver.step);
  set_field(L, "ratio", solver.ratio);
  set_field(L, "damping_rate", solver.damping_rate);
  if (!model.cycling_started()) set_field(L, "contacts", solver.contacts);
  set_field(L, "late_contacts", static_cast<long long>(solver.late_contacts));
  set_field(L, "contact_searches", static_cast<long long>(solver.contact_searches));
  set_field(L, "threads", solver.threads);
  if (model.cycling_started()) {  // contacts: counted when read (below)
    lua_createtable(L, 0, 2);
    lua_pushcfunction(L, count_contacts_when_read);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, pairs_with_contacts);
    lua_setfield(L, -2, "__pairs");
    lua_setmetatable(L, -2);
  }
  return 1;
}

int run_energy(lua_State* L, Context& context, const Args& args) {
  Model& model = context.model();
  // Either fails only from a callback, before anything is changed.
  if (args.has("by_contact")) model.book_energy_by_contact(args.boolean("by_contact"));
  if (args.has("reset") && args.boolean("reset")) model.reset_energy();
  const EnergyReport r = model.energy();
  lua_createtable(L, 0, 24);
  set_field(L, "kinetic", r.stored.kinetic);
  set_field(L, "strain", r.stored.strain);
  set_field(L, "contact", r.stored.contact());
  set_field(L, "contact_normal", r.stored.normal);
  set_field(L, "contact_shear", r.stored.shear);
  set_field(L, "bolt", r.stored.bolt);
  set_field(L, "gravity", r.gravity);
  set_field(L, "boundary", r.boundary);
  set_field(L, "release", r.release);
  set_field(L, "prestress", r.prestress);
  set_field(L, "commands", r.commands);
  set_field(L, "excavated", r.excavated);
  set_field(L, "plastic", r.plastic);
  set_field(L, "slip", r.slip);
  set_field(L, "bond", r.bond);
  set_field(L, "damping", r.damping);
  set_field(L, "bolt_plastic", r.bolt_plastic);
  set_field(L, "error", r.error);
  set_field(L, "largest", r.largest);
  set_field(L, "relative_error", r.relative_error());
  set_field(L, "zone_error", r.zone_error);
  set_field(L, "restarted", r.restarted);
  set_field(L, "contact_error", r.contact_error);
  set_field(L, "bolt_error", r.bolt_error);
  return 1;
}

// The innermost of the named regions `indices` (smallest area; the last defined on a tie).
int innermost(const Model& model, const std::vector<int>& indices) {
  int best = -1;
  double best_area = 0.0;
  for (const int r : indices) {
    const double area = std::fabs(signed_area(model.regions()[static_cast<size_t>(r)].polygon));
    if (best < 0 || area <= best_area) {
      best = r;
      best_area = area;
    }
  }
  return best;
}

// t.region = name of the innermost region, or nothing.
void set_region(lua_State* L, const Model& model, const std::vector<int>& regions) {
  const int r = innermost(model, regions);
  if (r >= 0) set_field(L, "region", model.regions()[static_cast<size_t>(r)].name);
}

void push_points(lua_State* L, const std::vector<Vec2>& points) {
  lua_createtable(L, static_cast<int>(points.size()), 0);
  for (size_t i = 0; i < points.size(); ++i) {
    push_point(L, points[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

void set_centroid(lua_State* L, Vec2 centroid) {
  push_point(L, centroid);
  lua_setfield(L, -2, "centroid");
  set_field(L, "x", centroid.x);
  set_field(L, "y", centroid.y);
}

int zone_count_of(const Mesh& mesh, size_t block) {
  if (block + 1 >= mesh.block_first_zone.size()) return 0;
  return mesh.block_first_zone[block + 1] - mesh.block_first_zone[block];
}

void push_block(lua_State* L, const Model& model, size_t index) {
  const Block& block = model.blocks().blocks[index];
  lua_createtable(L, 0, 14);
  set_field(L, "id", static_cast<long long>(index + 1));
  set_field(L, "area", block.area);
  set_centroid(L, block.centroid);
  push_points(L, block.outer.points);
  lua_setfield(L, -2, "vertices");
  lua_createtable(L, static_cast<int>(block.holes.size()), 0);
  for (size_t h = 0; h < block.holes.size(); ++h) {
    push_points(L, block.holes[h].points);
    lua_rawseti(L, -2, static_cast<lua_Integer>(h + 1));
  }
  lua_setfield(L, -2, "holes");
  set_field(L, "base", block.base + 1);
  set_field(L, "zones", zone_count_of(model.mesh(), index));
  set_region(L, model, block.regions);
  lua_createtable(L, static_cast<int>(block.regions.size()), 0);
  for (size_t r = 0; r < block.regions.size(); ++r) {
    const auto& name = model.regions()[static_cast<size_t>(block.regions[r])].name;
    lua_pushlstring(L, name.data(), name.size());
    lua_rawseti(L, -2, static_cast<lua_Integer>(r + 1));
  }
  lua_setfield(L, -2, "regions");
  const BlockMotion motion = model.block_motion(static_cast<int>(index));
  set_field(L, "max_displacement", motion.max_displacement);
  if (motion.excavated > 0) set_field(L, "excavated", motion.excavated);
}

void push_zone(lua_State* L, const Model& model, size_t index) {
  const Mesh& mesh = model.mesh();
  const int zone = static_cast<int>(index);
  const auto& corners = mesh.zone_gp[index];
  const int block = mesh.zone_block[index];
  lua_createtable(L, 0, 9);
  set_field(L, "id", static_cast<long long>(index + 1));
  set_field(L, "area", mesh.zone_area(zone));
  set_centroid(L, mesh.zone_centroid(zone));
  std::vector<Vec2> points;
  lua_createtable(L, 3, 0);
  for (size_t k = 0; k < corners.size(); ++k) {
    points.push_back(mesh.gp_position[static_cast<size_t>(corners[k])]);
    lua_pushinteger(L, corners[k] + 1);
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  lua_setfield(L, -2, "gridpoints");
  push_points(L, points);
  lua_setfield(L, -2, "vertices");
  set_field(L, "block", block + 1);
  set_region(L, model, model.blocks().blocks[static_cast<size_t>(block)].regions);
  const ZoneView view = model.zone_view(zone);
  set_field(L, "sxx", view.sxx);
  set_field(L, "syy", view.syy);
  set_field(L, "sxy", view.sxy);
  set_field(L, "szz", view.szz);
  set_field(L, "s1", view.s1);
  set_field(L, "s3", view.s3);
  set_field(L, "state", zone_state_name(view.state));
  if (!view.material.empty()) set_field(L, "material", view.material);
  if (view.excavated > 0) set_field(L, "excavated", view.excavated);
  if (!view.history_name.empty()) set_field(L, view.history_name.c_str(), view.history);
  set_field(L, "plastic_work", view.plastic_work);
}

void push_gridpoint(lua_State* L, const Model& model, size_t index) {
  const GridpointView gp = model.gridpoint(static_cast<int>(index));
  lua_createtable(L, 0, 20);
  set_field(L, "id", static_cast<long long>(index + 1));
  push_point(L, gp.position);
  lua_setfield(L, -2, "position");
  set_field(L, "x", gp.position.x);
  set_field(L, "y", gp.position.y);
  set_field(L, "ux", gp.u.x);
  set_field(L, "uy", gp.u.y);
  set_field(L, "vx", gp.v.x);
  set_field(L, "vy", gp.v.y);
  set_field(L, "fx", gp.f.x);
  set_field(L, "fy", gp.f.y);
  lua_pushboolean(L, gp.fixed_x);
  lua_setfield(L, -2, "fixed_x");
  lua_pushboolean(L, gp.fixed_y);
  lua_setfield(L, -2, "fixed_y");
  set_field(L, "block", model.mesh().gp_block[index] + 1);
}

void push_contact(lua_State* L, const Model& model, size_t index) {
  const ContactView c = model.contact(static_cast<int>(index));
  lua_createtable(L, 0, 20);
  set_field(L, "id", static_cast<long long>(index) + 1);
  push_point(L, c.position);
  lua_setfield(L, -2, "position");
  set_field(L, "x", c.position.x);
  set_field(L, "y", c.position.y);
  push_point(L, c.normal);
  lua_setfield(L, -2, "normal");
  set_field(L, "length", c.length);
  set_field(L, "fn", c.fn);
  set_field(L, "fs", c.fs);
  set_field(L, "sn", c.length > 0.0 ? c.fn / c.length : 0.0);
  set_field(L, "tau", c.length > 0.0 ? c.fs / c.length : 0.0);
  set_field(L, "un", c.un);
  set_field(L, "overlap", c.overlap);
  set_field(L, "us", c.us);
  set_field(L, "slip", c.slip);
  set_field(L, "state", c.state);
  set_field(L, "kind", c.kind);
  set_field(L, "material", c.material);
  set_field(L, "block", c.block + 1);
  set_field(L, "other", c.other + 1);
  lua_pushboolean(L, c.corner);
  lua_setfield(L, -2, "corner");
  set_field(L, "face", c.face + 1);
  if (std::isfinite(c.energy_made)) set_field(L, "energy_made", c.energy_made);
}

int next_block(lua_State* L) {
  return iterator_step(
      L, "blocks", [](const Model& m) { return m.blocks().blocks.size(); }, push_block);
}

// blocks() less the blocks excavated and those whose gridpoints have all moved no more than
// the distance in upvalue 2. Mucking out asks this every few hundred cycles: the blocks passed
// over cost no table.
int next_moved_block(lua_State* L) {
  const auto moved = [](lua_State* state, const Model& m, size_t block) {
    const BlockMotion motion = m.block_motion(static_cast<int>(block));
    const double distance = lua_tonumber(state, lua_upvalueindex(2));
    return motion.excavated == 0 && motion.max_displacement > distance;
  };
  const auto count = [](const Model& m) { return m.blocks().blocks.size(); };
  return iterator_step(L, "moved_blocks", count, moved, push_block);
}

// loose_blocks(): upvalue 2 is a table whose keys are the ids (1-based) of the blocks found loose
// when the iterator was made.
int next_loose_block(lua_State* L) {
  const auto loose = [](lua_State* state, const Model&, size_t block) {
    lua_rawgeti(state, lua_upvalueindex(2), static_cast<lua_Integer>(block + 1));
    const bool found = lua_toboolean(state, -1);
    lua_pop(state, 1);
    return found;
  };
  const auto count = [](const Model& m) { return m.blocks().blocks.size(); };
  return iterator_step(L, "loose_blocks", count, loose, push_block);
}

int next_zone(lua_State* L) {
  return iterator_step(
      L, "zones", [](const Model& m) { return m.mesh().zone_gp.size(); }, push_zone);
}

int next_gridpoint(lua_State* L) {
  return iterator_step(
      L, "gridpoints", [](const Model& m) { return m.mesh().gp_position.size(); }, push_gridpoint);
}

int next_contact(lua_State* L) {
  return iterator_step(
      L, "contacts", [](const Model& m) { return static_cast<size_t>(m.contact_count()); }, push_contact);
}

int run_contacts(lua_State* L, Context&, const Args&) {
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, next_contact, 1);
  return 1;
}

int run_contact_near(lua_State* L, Context& context, const Args& args) {
  const Model& model = context.model();
  const int contact = model.contact_near({args.number("x"), args.number("y")});
  if (contact < 0) {
    lua_pushnil(L);
    return 1;
  }
  push_contact(L, model, static_cast<size_t>(contact));
  return 1;
}

int run_gp_near(lua_State* L, Context& context, const Args& args) {
  const Model& model = context.model();
  const int gp = model.gridpoint_near({args.number("x"), args.number("y")});
  if (gp < 0) {
    lua_pushnil(L);
    return 1;
  }
  push_gridpoint(L, model, static_cast<size_t>(gp));
  return 1;
}

int run_zone_at(lua_State* L, Context& context, const Args& args) {
  const Model& model = context.model();
  const int zone = model.zone_at({args.number("x"), args.number("y")});
  if (zone < 0) {
    lua_pushnil(L);
    return 1;
  }
  push_zone(L, model, static_cast<size_t>(zone));
  return 1;
}

int run_gridpoints(lua_State* L, Context&, const Args&) {
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, next_gridpoint, 1);
  return 1;
}

int run_blocks(lua_State* L, Context&, const Args&) {
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, next_block, 1);
  return 1;
}

int run_moved_blocks(lua_State* L, Context&, const Args& args) {
  lua_pushinteger(L, 0);
  lua_pushnumber(L, args.number("distance"));
  lua_pushcclosure(L, next_moved_block, 2);
  return 1;
}

int run_loose_blocks(lua_State* L, Context& context, const Args& args) {
  const std::vector<int> loose = context.model().loose_blocks(args.has("speed") ? args.number("speed") : 0.0);
  lua_pushinteger(L, 0);
  lua_createtable(L, 0, static_cast<int>(loose.size()));
  for (const int block : loose) {
    lua_pushboolean(L, 1);
    lua_rawseti(L, -2, static_cast<lua_Integer>(block + 1));
  }
  lua_pushcclosure(L, next_loose_block, 2);
  return 1;
}

int run_zones(lua_State* L, Context&, const Args&) {
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, next_zone, 1);
  return 1;
}

}  // namespace

const Command& info_command() {
  static const Command command{
      .name = "info",
      .help = "Counts and solver state of the current model.",
      .form = Form::call,
      .run = run_info,
      .returns =
          "a table: blocks, zones, gridpoints, joint_edges, dropped_cuts, cuts_left_out (pieces of "
          "crackseed{ auto }'s cuts, or of its groups' outlines where no cut was left to give way, left "
          "out where no bending of the cuts kept them the model's tolerance apart, or near where "
          "joints they had bent kept coming closer), cuts_cut_back (its cuts cut back from a corner sharper than its min_angle), "
          "snapped (features smaller than the tolerance, zone{ sliver } of the zones there, that cuts were bent "
          "together to remove), slivers_kept (spots where required cuts crossing at a shallow angle "
          "could not be bent clear of it: their slivers kept), shortest_edge (the shortest block edge over the "
          "zone edge there), regions, "
          "joint_sets, crack_seeds, sections (potential-crack sections), intact_sections (not broken, and not gone "
          "with their rock: sections()), "
          "cracks, shear_cracks, tension_cracks, stage (excavations so far), title, cycle (cycles run so far), time (model time [s]; static mode: "
          "the cycle count), step (time step [s]), ratio (last unbalanced-force ratio), "
          "damping_rate (adaptive damping's c = 2 omega [1/s] as last set, from the Rayleigh quotient of "
          "the displacement since the cycling command began: it falls as sliding rock takes that "
          "displacement over; 0 under local damping or none), "
          "contacts (those there are now, as contacts() counts them; before the first cycle as last found: 0 "
          "until a contact query), late_contacts "
          "(contacts found already pressed in by more than a tenth of their reach, since the "
          "blocks were zoned: detection came too late for them; it should stay 0), contact_searches "
          "(gridpoints whose contacts have been searched for since the blocks were zoned: the cost of "
          "detection, which searches again only near blocks that moved), threads (those cycling uses: "
          "--threads, else the cores the process may run on, no more than the model keeps busy, and fewer "
          "while its threads wait for each other because another process holds a core; before the first "
          "cycle, those asked for)",
      .usage = "print(info().blocks)",
  };
  return command;
}

const Command& energy_command() {
  static const Command command{
      .name = "energy",
      .help =
          "The energy balance since the first cycle (or the last reset), as PFC and 3DEC keep it, "
          "per metre of thickness [J/m]: the work done on the model, what it stores (as changes "
          "since the start), what it dissipated, and the balance's error, the energy the numerical "
          "method made.",
      .keys =
          {
              {"reset", Type::boolean, "", any_value, "false",
               "start the balance again from the state now (not from a callback)"},
              {"by_contact", Type::boolean, "", any_value, kOptional,
               "each contact keeps its own balance from now, from nothing: contacts() then gives "
               "each its energy_made, to find the contacts that make or lose energy (each contact's "
               "energy is then found twice a cycle; not kept in checkpoints; not from a callback)"},
          },
      .run = run_energy,
      .returns =
          "a table [J/m]. Stored (change since the start): kinetic, strain (zones' elastic "
          "energy), contact (= contact_normal + contact_shear: the joints' springs), bolt (segments "
          "and grout). Work done on the model: gravity, boundary (boundary loads, moving held "
          "gridpoints, bolt head drives), release (the loads excavate{ release } takes off), "
          "prestress (stored in contacts made with a given stress: insitu{}'s, or a broken "
          "section's traction), commands (stored energy changed by commands between cycles: "
          "insitu{}, reset{}, new properties). Taken away: excavated (by excavate{}, dug or "
          "mucked out). Dissipated: plastic (zones), slip (joints' Coulomb slip), bond (bonds that "
          "soften or break, cohesive faces that part), damping, bolt_plastic (yield, breaks, grout "
          "slip). error: stored + dissipated + excavated less the work done (positive: energy "
          "made); largest: the largest term in magnitude; relative_error = error / largest; "
          "zone_error, contact_error, bolt_error: where the error arises; restarted: of "
          "contact_error, what contacts made (negative: lost) where a detection found one on "
          "another face of the block its gridpoint presses into and it started anew there (a "
          "gridpoint pressed in about as deep as that block is thick)",
      .usage = "local e = energy()\nprint(e.error, e.relative_error)\nenergy{ reset = true }\n"
               "energy{ by_contact = true }  -- then: for c in contacts() do print(c.id, c.energy_made) end",
      .bare_call = true,
  };
  return command;
}

const Command& blocks_command() {
  static const Command command{
      .name = "blocks",
      .help = "Iterates over the blocks.",
      .form = Form::call,
      .run = run_blocks,
      .returns =
          "an iterator; each block is a table: id, area, centroid {x =, y =}, x, y, "
          "vertices (list of points), holes (list of point lists), base (its block{} "
          "number), zones (count), region (innermost region's name or nil), regions "
          "(names of all regions containing it), max_displacement (the largest displacement of its "
          "gridpoints [m]), excavated (the last stage that excavated its zones, nil while any "
          "is in place)",
      .usage = "for b in blocks() do if b.region == \"cut\" then print(b.id, b.area) end end",
  };
  return command;
}

const Command& moved_blocks_command() {
  static const Command command{
      .name = "moved_blocks",
      .help = "Iterates over the blocks still in place that have moved more than a distance: what "
              "mucking out fallen rock looks for.",
      .form = Form::call,
      .positional =
          {
              {"distance", Type::number, "m", ge(0), kRequired,
               "how far a gridpoint of the block must have moved (more than this)"},
          },
      .run = run_moved_blocks,
      .returns = "an iterator over the blocks not excavated whose max_displacement is greater than "
                 "the distance, in id order; each block a table as `blocks()` gives",
      .usage = "for b in moved_blocks(1.0) do excavate{ block = b.id } end",
  };
  return command;
}

const Command& loose_blocks_command() {
  static const Command command{
      .name = "loose_blocks",
      .help = "Iterates over the blocks that have come loose: still in place, but (with the blocks glued "
              "to them) neither held by a boundary nor pressed against another block by any contact, "
              "or moving faster than `speed`: what mucking out takes. Under soft joints rock still in "
              "place can move a metre; this asks whether it is held.",
      .keys =
          {
              {"speed", Type::number, "m/s", ge(0), kOptional,
               "also loose: a block whose gridpoints' mean speed is above this (static mode: m per cycle)",
               "none: only blocks held by nothing"},
          },
      .run = run_loose_blocks,
      .returns = "an iterator over those blocks, in id order; each block a table as `blocks()` gives",
      .usage = "for b in loose_blocks{ speed = 1e-4 } do excavate{ block = b.id } end",
      .bare_call = true,
  };
  return command;
}

const Command& zones_command() {
  static const Command command{
      .name = "zones",
      .help = "Iterates over the zones (triangles) of the zoned blocks.",
      .form = Form::call,
      .run = run_zones,
      .returns =
          "an iterator; each zone is a table: id, area, centroid {x =, y =}, x, y, "
          "vertices (three points, counter-clockwise), gridpoints (their ids), block "
          "(its block's id), region (innermost region's name or nil), sxx, syy, sxy, szz "
          "(stresses [Pa], compression negative), s1, s3 (in-plane principal stresses, s1 <= "
          "s3), state (\"elastic\", \"shear\", \"tension\", ... with \"-past\" for failure "
          "in the past), plastic_work (the plastic work done in it per unit volume [J/m^3] "
          "since its state was last cleared: how far past its strength it went), material "
          "(name, nil when none is assigned), excavated (the stage that excavated it, nil "
          "while in place), and the state variable of its zone law under "
          "the law's name for it, when the law keeps one",
      .usage = "for z in zones() do total = total + z.area end",
  };
  return command;
}

const Command& gridpoints_command() {
  static const Command command{
      .name = "gridpoints",
      .help = "Iterates over the gridpoints (zone corners; distinct on the two sides of a joint).",
      .form = Form::call,
      .run = run_gridpoints,
      .returns =
          "an iterator; each gridpoint is a table: id, position {x =, y =}, x, y (where it was "
          "made [m]), ux, uy (displacement [m]), vx, vy (velocity [m/s]), fx, fy (unbalanced "
          "force of the last cycle [N/m]), fixed_x, fixed_y (true when held), block (its "
          "block's id)",
      .usage = "for gp in gridpoints() do umax = math.max(umax, math.abs(gp.uy)) end",
  };
  return command;
}

const Command& gp_near_command() {
  static const Command command{
      .name = "gp_near",
      .help = "The gridpoint nearest to a point.",
      .form = Form::call,
      .positional =
          {
              {"x", Type::number, "m", any_value, kRequired, "x of the point"},
              {"y", Type::number, "m", any_value, kRequired, "y of the point"},
          },
      .run = run_gp_near,
      .returns = "a gridpoint table as `gridpoints()` gives, or nil when the model has no zones",
      .usage = "local roof = gp_near(0, 24)",
  };
  return command;
}

const Command& zone_at_command() {
  static const Command command{
      .name = "zone_at",
      .help = "The zone containing a point.",
      .form = Form::call,
      .positional =
          {
              {"x", Type::number, "m", any_value, kRequired, "x of the point"},
              {"y", Type::number, "m", any_value, kRequired, "y of the point"},
          },
      .run = run_zone_at,
      .returns = "a zone table as `zones()` gives, or nil when no zone contains the point",
      .usage = "local z = zone_at(0, -30)",
  };
  return command;
}

const Command& contacts_command() {
  static const Command command{
      .name = "contacts",
      .help =
          "Iterates over the contacts: each gridpoint of a block boundary against the nearest "
          "edge of another block within reach, as found at the last detection (found now "
          "if cycling has not begun). Both faces of a joint have their gridpoints in contact, "
          "each with half the length, so the lengths along a joint add up to it.",
      .form = Form::call,
      .run = run_contacts,
      .returns =
          "an iterator; each contact is a table: id, position {x =, y =}, x, y (the "
          "gridpoint, where it is now [m]), normal {x =, y =} (unit, out of the edge's block), "
          "length [m] (the part that carries its force: less for a gridpoint past the corner "
          "of the other block), fn, fs (normal force, compression negative, and shear force "
          "[N/m]), sn, "
          "tau (the same per length [Pa]), un (normal displacement, opening positive, "
          "including the closure the in-situ stress gives and the dilation [m]), overlap (how far the "
          "gridpoint is inside the edge's block, its closure less a given prestress's, as its force "
          "takes it [m]; the overlap watchdog takes the lesser depth behind the lines of the free "
          "faces beside the edge's convex corners too), us (shear displacement since it "
          "formed [m]), slip (plastic shear, accumulated [m]), state (\"bonded\", "
          "\"elastic\", \"slip\", \"open\"), kind (\"joint\", \"crack\"), material, "
          "block and other (the gridpoint's and the edge's block ids), corner (true for each of the "
          "two contacts a gridpoint in a concave corner of the other block has, one on each face) and "
          "face (1, or 2 for the second of those two: a contact is the one of its gridpoint, other "
          "and face); with energy{ by_contact = "
          "true }, energy_made (the energy it made since the balance started: its stored energy's "
          "change and what it dissipated, less the work its nodes did on it, each cycle and at "
          "each detection [J/m]; a contact dropped takes its own with it)",
      .usage = "for c in contacts() do if c.state == \"slip\" then n = n + 1 end end",
  };
  return command;
}

const Command& contact_near_command() {
  static const Command command{
      .name = "contact_near",
      .help = "The contact whose gridpoint is nearest to a point.",
      .form = Form::call,
      .positional =
          {
              {"x", Type::number, "m", any_value, kRequired, "x of the point"},
              {"y", Type::number, "m", any_value, kRequired, "y of the point"},
          },
      .run = run_contact_near,
      .returns = "a contact table as `contacts()` gives, or nil when there are no contacts",
      .usage = "local c = contact_near(0, 0.5)",
  };
  return command;
}

}  // namespace edem
