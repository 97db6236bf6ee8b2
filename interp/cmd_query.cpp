// Reading the model from a script: info() and the iterators blocks() and zones().
//
// Iterators hold only a position and look the model up at each step, so a script that changes
// the model inside the loop sees the new model, never a dangling reference. Ids are 1-based.
#include <fmt/format.h>

#include <cmath>
#include <lua.hpp>

#include "adaptor.hpp"
#include "commands.hpp"
#include "context.hpp"
#include "geom/polygon.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

int run_info(lua_State* L, Context& context, const Args&) {
  Model& model = context.model();
  const ModelInfo info = model.info();
  lua_createtable(L, 0, 8);
  set_field(L, "blocks", info.blocks);
  set_field(L, "zones", info.zones);
  set_field(L, "gridpoints", info.gridpoints);
  set_field(L, "joint_edges", info.joint_edges);
  set_field(L, "dropped_cuts", info.dropped_cuts);
  set_field(L, "regions", info.regions);
  set_field(L, "joint_sets", info.joint_sets);
  set_field(L, "title", model.title());
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
  lua_createtable(L, 0, 12);
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
}

// One step of an iterator: upvalue 1 is the 0-based position of the next item.
template <typename Count, typename Push>
int step(lua_State* L, const char* name, Count&& count, Push&& push) {
  return guarded(L, name, [&] {
    const Model& model = context_of(L).model();
    const auto next = static_cast<size_t>(lua_tointeger(L, lua_upvalueindex(1)));
    if (next >= count(model)) return 0;
    lua_pushinteger(L, static_cast<lua_Integer>(next + 1));
    lua_replace(L, lua_upvalueindex(1));
    push(L, model, next);
    return 1;
  });
}

int next_block(lua_State* L) {
  return step(
      L, "blocks", [](const Model& m) { return m.blocks().blocks.size(); }, push_block);
}

int next_zone(lua_State* L) {
  return step(
      L, "zones", [](const Model& m) { return m.mesh().zone_gp.size(); }, push_zone);
}

int run_blocks(lua_State* L, Context&, const Args&) {
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, next_block, 1);
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
      .help = "Counts of the current model.",
      .form = Form::call,
      .run = run_info,
      .returns =
          "a table: blocks, zones, gridpoints, joint_edges, dropped_cuts, regions, "
          "joint_sets, title",
      .usage = "print(info().blocks)",
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
          "(names of all regions containing it)",
      .usage = "for b in blocks() do print(b.id, b.area) end",
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
          "(its block's id), region (innermost region's name or nil)",
      .usage = "for z in zones() do total = total + z.area end",
  };
  return command;
}

}  // namespace edem
