#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/names.hpp"
#include "geom/block_snap.hpp"
#include "geom/cutter.hpp"
#include "geom/joint_set.hpp"
#include "state/mechanics.hpp"
#include "solver/prepare.hpp"

namespace edem {
namespace {

void check_finite(double value, std::string_view what) {
  if (!std::isfinite(value)) fail("{} must be a finite number, got {}", what, value);
}

Box extent_of(const std::vector<BlockDef>& bases);

// A pattern's origin (jset, crackseed): its lines are laid one by one from the origin to the
// blocks, so one very many spacings away costs time and memory for nothing (the pattern repeats;
// an origin among the blocks gives the same lines). Up to 1e7 lines away (far-off map
// coordinates with a default origin at 0) is allowed.
void check_origin(Vec2 origin, const Box& blocks, double spacing) {
  check_coordinate(origin, "origin");
  const double away = std::max({blocks.x0 - origin.x, origin.x - blocks.x1, blocks.y0 - origin.y,
                                origin.y - blocks.y1, 0.0});
  if (away > 1e7 * spacing)
    fail("origin ({:g}, {:g}) is {:.3g} m from the blocks, {:.3g} spacings: its lines are laid from "
         "there; give an origin nearer them (the pattern repeats: one among them gives the same lines)",
         origin.x, origin.y, away, away / spacing);
}

Box extent_of(const std::vector<BlockDef>& bases) {
  Polygon all;
  for (const auto& base : bases) all.insert(all.end(), base.polygon.begin(), base.polygon.end());
  return bounding_box(all);
}

}  // namespace

Model::Model(ModelDef def) : def_(std::move(def)), mechanics_(std::make_unique<Mechanics>()) {
  if (!(def_.tolerance > 0.0 && def_.tolerance <= 1e-3))
    fail("tolerance must be in (0, 1e-3], got {}", def_.tolerance);
}

double Model::tolerance_of(const Inputs& inputs) const {
  const double size = inputs.bases.empty() ? 1.0 : extent_of(inputs.bases).diagonal();
  return def_.tolerance * size;
}

double Model::tolerance() const { return tolerance_of(inputs_); }

int Model::region_index(std::string_view name) const {
  std::vector<std::string> names;
  for (size_t i = 0; i < inputs_.regions.size(); ++i) {
    if (inputs_.regions[i].name == name) return static_cast<int>(i);
    names.push_back(inputs_.regions[i].name);
  }
  if (names.empty()) fail("unknown region '{}': no region{{}} has been defined", name);
  fail("unknown region '{}'{}", name, did_you_mean_or_list(name, names));
}

Polygon Model::resolve_in(const Inputs& inputs, const RegionRef& ref) const {
  if (ref.name.empty()) {
    validate_polygon(ref.polygon, "region polygon");
    return ref.polygon;
  }
  for (const auto& region : inputs.regions)
    if (region.name == ref.name) return region.polygon;
  return inputs.regions.at(static_cast<size_t>(region_index(ref.name))).polygon;  // throws
}

Polygon Model::resolve(const RegionRef& ref) const { return resolve_in(inputs_, ref); }

void Model::add_block(const BlockDef& def) {
  check_geometry_open();
  validate_polygon(def.polygon, "block");
  // A block thinner than the geometric tolerance cannot be cut or zoned (it is all sliver): say so
  // now rather than after minutes of mesh refinement.
  const double width = 2.0 * std::fabs(signed_area(def.polygon)) / perimeter(def.polygon);
  Inputs with = inputs_;
  with.bases.push_back(def);
  if (width < tolerance_of(with))
    fail("block is {:.3g} m wide (twice its area over its perimeter), thinner than the model's "
         "geometric tolerance, {:.3g} m: make it wider, or leave it out",
         width, tolerance_of(with));
  for (size_t i = 0; i < inputs_.bases.size(); ++i)
    if (interiors_overlap(def.polygon, inputs_.bases[i].polygon))
      fail("block overlaps block {} given earlier; blocks must not overlap", i + 1);
  Inputs next = inputs_;
  next.bases.push_back({counter_clockwise(def.polygon)});
  commit(std::move(next));
}

int Model::add_joint_set(const JointSetDef& def) {
  check_geometry_open();
  check_finite(def.angle, "angle");
  if (def.spacing.empty()) fail("spacing needs at least one value");
  double min_spacing = INFINITY;
  for (double s : def.spacing) {
    if (!(s > 0.0) || !std::isfinite(s)) fail("spacing must be > 0, got {}", s);
    min_spacing = std::min(min_spacing, s);
  }
  if (!(def.spacing_dev >= 0.0 && def.spacing_dev < min_spacing))
    fail("spacing_dev must be >= 0 and below the smallest spacing ({}), got {}", min_spacing,
         def.spacing_dev);
  if (!(def.trace > 0.0)) fail("trace must be > 0, got {}", def.trace);
  if (!(def.trace_dev >= 0.0 && (def.trace_dev < def.trace)))
    fail("trace_dev must be >= 0 and below trace ({}), got {}", def.trace, def.trace_dev);
  if (!(def.gap >= 0.0) || !std::isfinite(def.gap)) fail("gap must be >= 0, got {}", def.gap);
  if (!(def.gap_dev >= 0.0 && def.gap_dev <= def.gap))
    fail("gap_dev must be >= 0 and at most gap ({}), got {}", def.gap, def.gap_dev);
  if (!(def.angle_dev >= 0.0 && def.angle_dev < 90.0))
    fail("angle_dev must be in [0, 90), got {}", def.angle_dev);
  if (inputs_.bases.empty()) fail("no blocks to cut: define blocks with block{{...}} first");
  check_origin(def.origin, extent_of(inputs_.bases),
               *std::min_element(def.spacing.begin(), def.spacing.end()));
  if (!def.region.empty()) resolve(def.region);  // throws for an unknown name or bad polygon
  Inputs next = inputs_;
  next.joint_sets.push_back(def);
  commit(std::move(next));
  return static_cast<int>(inputs_.joint_sets.size()) - 1;
}

void Model::add_crack(const CrackDef& def) {
  check_geometry_open();
  check_coordinate(def.from, "crack end from");
  check_coordinate(def.to, "crack end to");
  if (norm(def.to - def.from) <= tolerance())
    fail("crack from ({}, {}) to ({}, {}) has zero length", def.from.x, def.from.y, def.to.x,
         def.to.y);
  if (inputs_.bases.empty()) fail("no blocks to cut: define blocks with block{{...}} first");
  Inputs next = inputs_;
  next.cracks.push_back(def);
  commit(std::move(next));
}

void Model::add_crackseed(const CrackSeedDef& def) {
  check_geometry_open();
  if (def.angles.empty() && def.cuts.empty()) fail("crackseed needs an angle: angle = a or angles = {{a1, a2}}");
  for (double a : def.angles) check_finite(a, "angle");
  if (!(def.spacing > 0.0) || !std::isfinite(def.spacing))
    fail("spacing must be > 0, got {}", def.spacing);
  if (inputs_.bases.empty()) fail("no blocks to cut: define blocks with block{{...}} first");
  check_origin(def.origin, extent_of(inputs_.bases), def.spacing);
  if (!def.region.empty()) resolve(def.region);  // throws for an unknown name or bad polygon
  Inputs next = inputs_;
  next.crack_seeds.push_back(def);
  commit(std::move(next));
}

void Model::add_region(const RegionDef& def) {
  check_geometry_open();
  if (def.name.empty()) fail("a region needs a name");
  for (const auto& region : inputs_.regions)
    if (region.name == def.name) fail("region '{}' is already defined", def.name);
  validate_polygon(def.polygon, "region polygon");
  Inputs next = inputs_;
  next.regions.push_back({def.name, counter_clockwise(def.polygon), def.glued});
  commit(std::move(next));
}

void Model::zone(const ZoneDef& def) {
  check_geometry_open();
  if (inputs_.bases.empty()) fail("no blocks to zone: define blocks with block{{...}} first");
  if (!(def.edge > 0.0) || !std::isfinite(def.edge)) fail("edge must be > 0, got {}", def.edge);
  const double far = def.far == 0.0 ? def.edge : def.far;
  if (!(far >= def.edge) || !std::isfinite(far))
    fail("far must be >= edge ({}), got {}", def.edge, far);
  if (!(def.growth > 0.0) || !std::isfinite(def.growth))
    fail("growth must be > 0, got {}", def.growth);
  if (!(def.sliver >= 0.0 && def.sliver <= 0.5)) fail("sliver must be in [0, 0.5], got {}", def.sliver);
  ZoneRequest request;
  request.sliver = def.sliver;
  request.size.edge = def.edge;
  request.size.far = far;
  request.size.growth = def.growth;
  for (const RegionRef& ref : def.near) request.size.near.push_back(resolve(ref));
  // Meshing too many zones takes minutes and gigabytes: refused before it, on an estimate.
  std::vector<Polygon> bases;
  for (const BlockDef& base : inputs_.bases) bases.push_back(base.polygon);
  const double zones = estimated_zone_count(bases, request.size);
  if (zones > def.max_zones)
    fail("these zones would be about {:.3g}, more than max_zones = {:.3g}: a larger edge (or far and near, "
         "fine only where it matters), blocks no thinner than their zones, or a larger max_zones",
         zones, def.max_zones);
  if (!def.region.name.empty())
    request.region = region_index(def.region.name);
  else if (!def.region.polygon.empty())
    request.polygon = resolve(def.region);
  Inputs next = inputs_;
  next.zone_requests.push_back(std::move(request));
  commit(std::move(next));
}

BlockSet Model::cut(const Inputs& inputs) const {
  CutInput input;
  input.tolerance = tolerance_of(inputs);
  // Where the blocks will be zoned, no edge shorter than a fraction of the zones there: the
  // finest any zone request asks for at the point (a block's own request is not known before it
  // is cut).
  if (std::any_of(inputs.zone_requests.begin(), inputs.zone_requests.end(),
                  [](const ZoneRequest& r) { return r.sliver > 0.0; })) {
    input.local_tolerance = [&inputs](Vec2 p) {
      double finest = INFINITY;
      for (const ZoneRequest& r : inputs.zone_requests)
        if (r.sliver > 0.0) finest = std::min(finest, r.sliver * r.size.at(p));
      return finest;
    };
    for (const ZoneRequest& r : inputs.zone_requests)
      input.largest_tolerance = std::max(input.largest_tolerance, r.sliver * r.size.far);
  }
  std::vector<Polygon> bases;
  for (const auto& base : inputs.bases) bases.push_back(base.polygon);
  int snapped = 0;
  input.bases = snap_blocks_together(bases, input.tolerance, &snapped);
  if (snapped > 0)
    for (size_t b = 0; b < input.bases.size(); ++b)
      validate_polygon(input.bases[b], fmt::format("block {} with its corners snapped to its neighbours'", b + 1));
  for (const auto& region : inputs.regions) {
    input.regions.push_back(region.polygon);
    input.region_glued.push_back(region.glued);
  }
  const Box extent = extent_of(inputs.bases);
  for (size_t set = 0; set < inputs.joint_sets.size(); ++set) {
    const JointSetDef& def = inputs.joint_sets[set];
    int clip = -1;
    if (!def.region.empty()) {
      clip = static_cast<int>(input.clip_polygons.size());
      input.clip_polygons.push_back(resolve_in(inputs, def.region));
    }
    const auto traces = joint_set_traces(def, extent, static_cast<int>(set), clip);
    input.cuts.insert(input.cuts.end(), traces.begin(), traces.end());
  }
  for (size_t i = 0; i < inputs.cracks.size(); ++i)
    input.cuts.push_back({inputs.cracks[i].from, inputs.cracks[i].to,
                          {EdgeKind::crack, -1, static_cast<int>(i), false}, -1});
  // Potential cracks: parallel cuts as a joint set lays them, glued (tied) until they break.
  for (size_t i = 0; i < inputs.crack_seeds.size(); ++i) {
    const CrackSeedDef& seed = inputs.crack_seeds[i];
    int clip = -1;
    if (!seed.region.empty()) {
      clip = static_cast<int>(input.clip_polygons.size());
      input.clip_polygons.push_back(resolve_in(inputs, seed.region));
    }
    // The automatic ones (they come with an outline) are laid where the prepass yielded, not
    // where a user drew them: one that cannot be laid the tolerance clear of the rest is left out.
    const bool optional = !seed.outline.empty();
    for (const auto& [a, b] : seed.cuts)
      input.cuts.push_back({a, b, {EdgeKind::potential, -1, static_cast<int>(i), true}, clip, optional,
                            optional ? seed.min_angle : 0.0});
    for (const auto& [a, b] : seed.outline)
      input.cuts.push_back({a, b, {EdgeKind::region, -1, -1, true}, -1, false, 0.0, true});
    if (!seed.cuts.empty()) continue;
    for (const double angle : seed.angles) {
      JointSetDef lines;
      lines.angle = angle;
      lines.spacing = {seed.spacing};
      lines.origin = seed.origin;
      for (CutSegment cut : joint_set_traces(lines, extent, -1, clip)) {
        cut.origin = {EdgeKind::potential, -1, static_cast<int>(i), true};
        input.cuts.push_back(cut);
      }
    }
  }
  check_block_count(inputs, input);
  BlockSet blocks = cut_blocks(input);
  blocks.snapped_vertices += snapped;
  return blocks;
}

// Refuses, before any cutting, cuts that would make more than max_blocks blocks: about one a
// base, one a line or cut, and one a crossing of two families of parallel lines (the area they
// share over the product of their spacings, times the sine between them; a trace's share of its
// line where traces have gaps).
void Model::check_block_count(const Inputs& inputs, const CutInput& input) const {
  struct Family {
    double angle, spacing, persistence, area;
  };
  double total_area = 0.0;
  for (const Polygon& base : input.bases) total_area += std::fabs(signed_area(base));
  const auto area_of = [&](const RegionRef& region) {
    return region.empty() ? total_area : std::min(total_area, std::fabs(signed_area(resolve_in(inputs, region))));
  };
  std::vector<Family> families;
  for (const JointSetDef& def : inputs.joint_sets) {
    const double spacing = *std::min_element(def.spacing.begin(), def.spacing.end());
    const double persistence = std::isfinite(def.trace) ? def.trace / (def.trace + def.gap) : 1.0;
    families.push_back({def.angle, spacing, persistence, area_of(def.region)});
  }
  for (const CrackSeedDef& seed : inputs.crack_seeds)
    if (seed.cuts.empty())
      for (const double angle : seed.angles) families.push_back({angle, seed.spacing, 1.0, area_of(seed.region)});
  double blocks = static_cast<double>(input.bases.size() + input.cuts.size());
  for (size_t f = 0; f < families.size(); ++f)
    for (size_t g = f + 1; g < families.size(); ++g) {
      const Family &a = families[f], &b = families[g];
      const double sine = std::fabs(std::sin((a.angle - b.angle) * std::numbers::pi / 180.0));
      blocks += std::min(a.area, b.area) * sine * a.persistence * b.persistence / (a.spacing * b.spacing);
    }
  if (blocks > def_.max_blocks)
    fail("these cuts would make about {:.3g} blocks, more than max_blocks = {:.3g}: larger spacings, joint sets "
         "and crack seeds in a region near where they matter, or model{{ max_blocks = ... }}",
         blocks, def_.max_blocks);
}

std::vector<const SizeField*> Model::size_fields(const Inputs& inputs, const BlockSet& blocks) const {
  // Each block takes the last zoning request that covers it.
  std::vector<const SizeField*> size_of_block(blocks.blocks.size(), nullptr);
  for (size_t b = 0; b < blocks.blocks.size(); ++b) {
    const Block& block = blocks.blocks[b];
    for (const ZoneRequest& request : inputs.zone_requests) {
      const bool covers =
          request.region >= 0
              ? std::count(block.regions.begin(), block.regions.end(), request.region) > 0
              : !request.polygon || contains(*request.polygon, block.centroid);
      if (covers) size_of_block[b] = &request.size;
    }
  }
  return size_of_block;
}

Mesh Model::zone_all(const Inputs& inputs, const BlockSet& blocks) const {
  return zone_blocks(blocks, size_fields(inputs, blocks));
}

void Model::check_geometry_open() const {
  if (restored_)
    fail("the geometry of a model restored from a checkpoint cannot change; make the change in the script "
         "that builds the model, before its save()");
  if (cycling_started())
    fail("the geometry cannot change once cycling has begun (cycle {})", solver_info().cycle);
}

void Model::commit(Inputs next) {
  BlockSet blocks = cut(next);
  Mesh mesh = zone_all(next, blocks);
  inputs_ = std::move(next);
  blocks_ = std::move(blocks);
  mesh_ = std::move(mesh);
  prepass_yield_.clear();  // it was for the old zones
  last_prepass_.reset();
  // New zones: the mechanical commands given so far are applied to them again.
  Mechanics& m = *mechanics_;
  m.crack_seeds = inputs_.crack_seeds;
  reset_for_mesh(m, mesh_);
  if (mesh_.zone_count() == 0) return;
  m.replaying = true;
  struct Done {
    bool& flag;
    ~Done() { flag = false; }
  } done{m.replaying};
  for (const auto& command : m.replay) command(*this);
}

ModelInfo Model::info() const {
  ModelInfo info;
  info.blocks = static_cast<int>(blocks_.blocks.size());
  info.zones = mesh_.zone_count();
  info.gridpoints = mesh_.gp_count();
  info.joint_edges = blocks_.joint_edges;
  info.dropped_cuts = blocks_.dropped_cuts;
  info.cuts_left_out = blocks_.cuts_left_out;
  info.cuts_cut_back = blocks_.cuts_cut_back;
  info.snapped = blocks_.snapped_vertices;
  info.slivers_kept = blocks_.slivers_kept;
  const std::vector<const SizeField*> sizes = size_fields(inputs_, blocks_);
  for (size_t b = 0; b < blocks_.blocks.size(); ++b) {
    if (!sizes[b]) continue;
    const Block& block = blocks_.blocks[b];
    std::vector<const Ring*> rings{&block.outer};
    for (const Ring& hole : block.holes) rings.push_back(&hole);
    for (const Ring* ring : rings)
      for (size_t i = 0; i < ring->points.size(); ++i) {
        const Vec2 a = ring->points[i], c = ring->points[(i + 1) % ring->points.size()];
        const double ratio = norm(c - a) / sizes[b]->at(0.5 * (a + c));
        if (info.shortest_edge == 0.0 || ratio < info.shortest_edge) info.shortest_edge = ratio;
      }
  }
  info.regions = static_cast<int>(inputs_.regions.size());
  info.joint_sets = static_cast<int>(inputs_.joint_sets.size());
  info.crack_seeds = static_cast<int>(inputs_.crack_seeds.size());
  add_crack_counts(info);
  info.stage = stage();
  return info;
}

}  // namespace edem
