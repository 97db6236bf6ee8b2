// Model::save and Model::restore: every member that a later cycle, query or picture reads, by
// name, in an HDF5 checkpoint (io/checkpoint_file.hpp, io/h5_archive.hpp).
//
// The derived solver arrays are stored too, not rebuilt: a rebuild at another moment than the
// uninterrupted run's would change the time step or the masses, and the run would no longer go
// on bit for bit. Only the split among threads is made again (the bits do not depend on it).
// Lua functions (callbacks, fn histories, a judge criterion, the commands replayed after a
// re-zone) cannot be stored; Model::restore leaves them for the script to give again.
#include <ctime>
#include <new>

#include "core/error.hpp"
#include "constitutive/zone_law.hpp"
#include "contact/detect.hpp"
#include "contact/joint_law.hpp"
#include "io/checkpoint_file.hpp"
#include "io/h5_archive.hpp"
#include "model/model.hpp"
#include "state/mechanics.hpp"
#include "solver/prepare.hpp"

namespace edem {

// ---- What each stored type holds. One list serves writing and reading; a member left out here
// is lost in a checkpoint, so each list follows its struct's declaration.

template <class Ar> void fields(Ar& ar, RegionRef& r) { ar("name", r.name); ar("polygon", r.polygon); }
// A member that files of the same schema written before it existed lack: `fallback` then.
template <class Ar, class T>
void optional_member(Ar& ar, const char* name, T& value, T fallback) {
  std::optional<T> read = value;
  ar(name, read);
  value = read.value_or(fallback);
}
template <class Ar> void fields(Ar& ar, BlockDef& b) { ar("polygon", b.polygon); }
template <class Ar> void fields(Ar& ar, JointSetDef& j) {
  ar("angle", j.angle); ar("spacing", j.spacing); ar("origin", j.origin); ar("trace", j.trace);
  ar("gap", j.gap); ar("angle_dev", j.angle_dev); ar("spacing_dev", j.spacing_dev);
  ar("trace_dev", j.trace_dev); ar("gap_dev", j.gap_dev); ar("seed", j.seed); ar("region", j.region);
}
template <class Ar> void fields(Ar& ar, CrackDef& c) { ar("from", c.from); ar("to", c.to); }
template <class Ar> void fields(Ar& ar, CrackSeedDef& c) {
  ar("region", c.region); ar("angles", c.angles); ar("spacing", c.spacing); ar("origin", c.origin);
  ar("material", c.material); ar("after", c.after); ar("cuts", c.cuts); ar("outline", c.outline);
  optional_member(ar, "min_angle", c.min_angle, 0.0);  // schema-1 files written before it have none
}
template <class Ar> void fields(Ar& ar, RegionDef& r) { ar("name", r.name); ar("polygon", r.polygon); ar("glued", r.glued); }
template <class Ar> void fields(Ar& ar, SizeField& f) {
  ar("edge", f.edge); ar("far", f.far); ar("growth", f.growth); ar("near", f.near);
}
template <class Ar> void fields(Ar& ar, EdgeOrigin& e) {
  ar("kind", e.kind); ar("set", e.set); ar("source", e.source); ar("glued", e.glued);
}
template <class Ar> void fields(Ar& ar, ZoneLawTable& t) { ar("key", t.key); ar("points", t.points); }
template <class Ar> void fields(Ar& ar, MaterialDef& m) {
  ar("name", m.name); ar("model", m.model); ar("density", m.density); ar("young", m.young);
  ar("poisson", m.poisson); ar("bulk", m.bulk); ar("shear", m.shear); ar("cohesion", m.cohesion);
  ar("friction", m.friction); ar("dilation", m.dilation); ar("tension", m.tension);
  optional_member(ar, "tables", m.tables, {});  // files older than zone-law tables have none
}
template <class Ar> void fields(Ar& ar, MaterialParams& p) {
  ar("model", p.model); ar("density", p.density); ar("bulk", p.bulk); ar("shear", p.shear); ar("e1", p.e1);
  ar("e2", p.e2); ar("cohesion", p.cohesion); ar("nphi", p.nphi); ar("npsi", p.npsi); ar("csnp", p.csnp);
  ar("tension", p.tension);
  optional_member(ar, "law_data", p.law_data, {});
}
template <class Ar> void fields(Ar& ar, SolverSettings& s) {
  ar("mode", s.mode); ar("damping", s.damping); ar("local_damping", s.local_damping); ar("step", s.step);
  ar("step_fraction", s.step_fraction); ar("mixed", s.mixed);
  optional_member(ar, "overlap", s.overlap, 0.0);  // files older than set{ overlap } have none
}
template <class Ar> void fields(Ar& ar, InsituDef& d) {
  ar("from_surface", d.from_surface); ar("sxx", d.sxx); ar("syy", d.syy); ar("sxy", d.sxy); ar("szz", d.szz);
  ar("ygrad", d.ygrad); ar("surface", d.surface); ar("density", d.density); ar("k0", d.k0);
  ar("surcharge", d.surcharge); ar("gravity", d.gravity); ar("region", d.region);
}
template <class Ar> void fields(Ar& ar, JointMaterialDef& j) {
  ar("name", j.name); ar("kn", j.kn); ar("ks", j.ks); ar("friction", j.friction); ar("cohesion", j.cohesion);
  ar("tension", j.tension); ar("residual_cohesion", j.residual_cohesion);
  ar("residual_friction", j.residual_friction); ar("dilation", j.dilation); ar("law", j.law);
  ar("kn_table", j.kn_table);
  // Optional: schema-1 files written before softening bonds have none (theirs dropped at once).
  optional_member(ar, "fracture_energy", j.fracture_energy, 0.0);
  optional_member(ar, "shear_fracture_energy", j.shear_fracture_energy, 0.0);
  optional_member(ar, "law_stress_scale", j.law_stress_scale, 1.0);  // 1: the law unscaled
  optional_member(ar, "law_closure_scale", j.law_closure_scale, 1.0);
}
template <class Ar> void fields(Ar& ar, JointParams& p) {
  ar("law", p.law); ar("kn", p.kn); ar("ks", p.ks); ar("tan_friction", p.tan_friction); ar("cohesion", p.cohesion);
  ar("tension", p.tension); ar("residual_cohesion", p.residual_cohesion);
  ar("tan_residual_friction", p.tan_residual_friction); ar("tan_dilation", p.tan_dilation);
  ar("stage_closure", p.stage_closure); ar("stage_kn", p.stage_kn); ar("stage_stress", p.stage_stress);
  ar("kn_zero", p.kn_zero); ar("kn_max", p.kn_max);
  optional_member(ar, "softens", p.softens, false);  // as the material's fracture energies
  optional_member(ar, "opening_at_loss", p.opening_at_loss, 0.0);
  optional_member(ar, "slip_at_loss", p.slip_at_loss, 0.0);
  optional_member(ar, "law_stress_scale", p.law_stress_scale, 1.0);
  optional_member(ar, "law_closure_scale", p.law_closure_scale, 1.0);
  // Files older than it: -1, and restore takes it from the joint material again.
  optional_member(ar, "curve_closure", p.curve_closure, -1.0);
}
template <class Ar> void fields(Ar& ar, JassignDef& j) {
  ar("material", j.material); ar("set", j.set); ar("kind", j.kind); ar("region", j.region);
}
template <class Ar> void fields(Ar& ar, Stress& s) { ar("xx", s.xx); ar("yy", s.yy); ar("xy", s.xy); ar("zz", s.zz); }
template <class Ar> void fields(Ar& ar, BoundarySegment& b) {
  ar("a", b.a); ar("b", b.b); ar("loaded", b.loaded); ar("at_a", b.at_a); ar("at_b", b.at_b);
}
template <class Ar> void fields(Ar& ar, ContactEdge& e) {
  ar("a", e.a); ar("b", e.b); ar("block", e.block); ar("prev", e.prev); ar("next", e.next);
  ar("corner_a", e.corner_a); ar("corner_b", e.corner_b); ar("bent_a", e.bent_a); ar("bent_b", e.bent_b);
  ar("touchable", e.touchable); ar("origin", e.origin); ar("material", e.material);
}
// Older schema-1 files may lack the bent flags: their contacts keep to the edge's line past any end.
std::vector<const char*> later_members(const ContactEdge*) { return {"bent_a", "bent_b"}; }
template <class Ar> void fields(Ar& ar, ContactBoundary& b) {
  ar("edges", b.edges); ar("block_first_edge", b.block_first_edge); ar("nodes", b.nodes);
  ar("edge_first", b.edge_first); ar("node_edges", b.node_edges); ar("block_first", b.block_first);
  ar("node_blocks", b.node_blocks); ar("reach", b.reach); ar("min_reach", b.min_reach);
  optional_member(ar, "median_edge", b.median_edge, 0.0);  // files older than it: found on restore
  ar("touchable_blocks", b.touchable_blocks);
}
template <class Ar> void fields(Ar& ar, Contact& c) {
  ar("node", c.node); ar("block", c.block); ar("other", c.other); ar("edge", c.edge); ar("material", c.material);
  ar("length", c.length); ar("limit", c.limit); ar("t", c.t); ar("share", c.share); ar("closure0", c.closure0);
  ar("dilation", c.dilation); ar("closure", c.closure); ar("sn", c.sn); ar("fs", c.fs); ar("us", c.us);
  ar("slip", c.slip); ar("fx", c.fx); ar("fy", c.fy); ar("state", c.state); ar("intact", c.intact);
  ar("wedge", c.wedge);
  ar("leads_past_a", c.leads_past_a);
  ar("leads_past_b", c.leads_past_b);
  ar("opened", c.opened);
  ar("far_a", c.far_a);
  ar("far_b", c.far_b);
  ar("per_facing", c.per_facing);
  ar("given", c.given);
  ar("face", c.face);
  ar("split", c.split);
  ar("half_a", c.half_a);
  ar("half_b", c.half_b);
  ar("pair_at_a", c.pair_at_a);
  ar("pair_at_b", c.pair_at_b);
}
// Older schema-1 files may lack these, read then at their defaults: a tip's own length (such
// files have no tips), the leads_past flags (their tips fade past any corner), a softening
// bond's opening (they have no softening bonds), the facing a length follows (theirs hold
// the length found until the next detection) and a gridpoint's second contact with a block (they
// have none; so their facing lengths count both half-edges).
std::vector<const char*> later_members(const Contact*) {
  return {"wedge", "leads_past_a", "leads_past_b", "opened", "far_a", "far_b", "per_facing", "given", "face",
          "split", "half_a", "half_b", "pair_at_a", "pair_at_b"};
}
template <class Ar> void fields(Ar& ar, ContactSet& s) {
  ar("list", s.list); ar("gather_first", s.gather_first); ar("gather", s.gather); ar("rows", s.rows);
  ar("x_detected", s.x_detected); ar("detected", s.detected); ar("as_built", s.as_built);
  ar("from_insitu", s.from_insitu); ar("late", s.late); ar("searched", s.searched);
  ar("partial", s.partial);
  optional_member(ar, "facing_known", s.facing_known, false);  // files older than it: not known
  optional_member(ar, "split_from", s.split_from, {});  // files older than it: nothing taken over
}
// Files written before detection was done block by block lack these (and had only full ones).
std::vector<const char*> later_members(const ContactSet*) { return {"searched", "partial"}; }
template <class Ar> void fields(Ar& ar, Section& s) {
  ar("a", s.a); ar("b", s.b); ar("edge", s.edge); ar("block", s.block); ar("seed", s.seed); ar("point", s.point);
  ar("angle", s.angle); ar("length", s.length); ar("mode", s.mode); ar("crack", s.crack); ar("fresh", s.fresh);
}
template <class Ar> void fields(Ar& ar, RockStrength& r) {
  ar("cohesion", r.cohesion); ar("friction", r.friction); ar("tension", r.tension);
}
template <class Ar> void fields(Ar& ar, SectionFits& f) {
  ar("first", f.first); ar("zone", f.zone); ar("weight", f.weight); ar("offset", f.offset); ar("body", f.body);
  ar("strength", f.strength); ar("after", f.after);
}
template <class Ar> void fields(Ar& ar, CrackView& c) {
  ar("id", c.id); ar("section", c.section); ar("position", c.position); ar("angle", c.angle);
  ar("length", c.length); ar("mode", c.mode); ar("cycle", c.cycle); ar("stage", c.stage); ar("sxx", c.sxx);
  ar("syy", c.syy); ar("sxy", c.sxy);
}
template <class Ar> void fields(Ar& ar, ReleaseLoad& r) {
  ar("dof", r.dof); ar("force", r.force); ar("cycles", r.cycles); ar("done", r.done); ar("factor", r.factor);
}
template <class Ar> void fields(Ar& ar, BoltMaterialDef& b) {
  ar("name", b.name); ar("young", b.young); ar("area", b.area); ar("density", b.density);
  ar("yield_tension", b.yield_tension); ar("yield_compression", b.yield_compression);
  ar("failure_strain", b.failure_strain); ar("bond_stiffness", b.bond_stiffness);
  ar("bond_strength", b.bond_strength); ar("spacing", b.spacing);
}
template <class Ar> void fields(Ar& ar, BoltLaw& b) {
  ar("ea", b.ea); ar("yield_tension", b.yield_tension); ar("yield_compression", b.yield_compression);
  ar("failure_strain", b.failure_strain); ar("bond_stiffness", b.bond_stiffness);
  ar("bond_strength", b.bond_strength); ar("line_mass", b.line_mass);
}
template <class Ar> void fields(Ar& ar, BoltNodes& n) {
  ar("x", n.x); ar("u", n.u); ar("v", n.v); ar("force", n.force); ar("mass", n.mass); ar("tributary", n.tributary);
  ar("bond_length", n.bond_length); ar("grout_stiffness", n.grout_stiffness);
  ar("grout_strength", n.grout_strength); ar("axis", n.axis); ar("grout_force", n.grout_force);
  ar("grout_slip", n.grout_slip); ar("slipping", n.slipping); ar("grout_rel", n.grout_rel);
}
template <class Ar> void fields(Ar& ar, BoltSegments& s) {
  ar("a", s.a); ar("b", s.b); ar("material", s.material); ar("rest", s.rest); ar("elongation", s.elongation);
  ar("direction", s.direction); ar("force", s.force); ar("state", s.state);
  // Files older than it have none: then a segment has broken if its state says so (one broken and
  // cut away since, which those files forgot, cannot be told).
  std::optional<std::vector<std::uint8_t>> broke = s.broke;
  ar("broke", broke);
  if (broke) {
    s.broke = std::move(*broke);
  } else {
    s.broke.clear();
    for (SegmentState state : s.state) s.broke.push_back(state == SegmentState::broken ? 1 : 0);
  }
}
template <class Ar> void fields(Ar& ar, BoltSet& b) {
  ar("laws", b.laws); ar("nodes", b.nodes); ar("segments", b.segments); ar("bolt_first_node", b.bolt_first_node);
  ar("bolt_first_segment", b.bolt_first_segment);
}
template <class Ar> void fields(Ar& ar, BoltHosts& h) {
  ar("zone", h.zone); ar("weight", h.weight); ar("u0", h.u0); ar("host_u", h.host_u); ar("slide", h.slide);
  ar("dir", h.dir); ar("rate", h.rate); ar("mass", h.mass); ar("slide_start", h.slide_start);
  ar("r_start", h.r_start); ar("material", h.material); ar("stage", h.stage); ar("removed", h.removed);
  ar("drive", h.drive); ar("drive_value", h.drive_value); ar("head_force", h.head_force);
  ar("gather_first", h.gather_first); ar("gather", h.gather); ar("rows", h.rows);
  ar("critical_step", h.critical_step);
}
template <class Ar> void fields(Ar& ar, ZoneGeometry& g) { ar("node", g.node); ar("area", g.area); ar("b", g.b); ar("c", g.c); }
template <class Ar> void fields(Ar& ar, SolverInfo& i) {
  ar("cycle", i.cycle); ar("time", i.time); ar("step", i.step); ar("ratio", i.ratio); ar("kinetic", i.kinetic);
  ar("contacts", i.contacts); ar("late_contacts", i.late_contacts);
}
template <class Ar> void fields(Ar& ar, AdaptiveDamping& a) {
  ar("c", a.c); ar("u_start", a.u_start); ar("r_start", a.r_start); ar("have_r_start", a.have_r_start);
}
template <class Ar> void fields(Ar& ar, StoredEnergy& e) {
  ar("kinetic", e.kinetic); ar("strain", e.strain); ar("normal", e.normal); ar("shear", e.shear); ar("bolt", e.bolt);
}
template <class Ar> void fields(Ar& ar, EnergyLedger& e) {
  ar("started", e.started); ar("start", e.start); ar("last", e.last); ar("last_current", e.last_current);
  ar("gravity", e.gravity); ar("boundary", e.boundary); ar("release", e.release); ar("prestress", e.prestress);
  ar("commands", e.commands); ar("excavated", e.excavated); ar("plastic", e.plastic); ar("slip", e.slip);
  ar("bond", e.bond); ar("damping", e.damping); ar("bolt_plastic", e.bolt_plastic); ar("by_contacts", e.by_contacts);
  ar("by_bolts", e.by_bolts);
  optional_member(ar, "restarted", e.restarted, 0.0);  // files written before it have none
}
template <class Ar> void fields(Ar& ar, History& h) {
  ar("name", h.name); ar("every", h.every); ar("unit", h.unit); ar("quantity", h.quantity); ar("at", h.at);
  ar("cycles", h.cycles); ar("values", h.values);
  // Optional: files written before histories followed their rock have none (found again from `at`).
  optional_member(ar, "node", h.node, -1); optional_member(ar, "zone", h.zone, -1);
  optional_member(ar, "ended", h.ended, std::string());
}
template <class Ar> void fields(Ar& ar, LoadStep& s) {
  ar("from", s.from); ar("to", s.to); ar("converged", s.converged); ar("residuals", s.residuals);
}
template <class Ar> void fields(Ar& ar, StageLog& l) {
  ar("steps", l.steps); ar("iterations", l.iterations); ar("cutbacks", l.cutbacks); ar("scale", l.scale);
  ar("seconds", l.seconds);
  // Optional: schema-1 files written before a prepass could stop short have neither.
  optional_member(ar, "failure", l.failure, std::string());
  optional_member(ar, "reached", l.reached, 1.0);
}
template <class Ar> void fields(Ar& ar, PrepassStage& s) { ar("name", s.name); ar("log", s.log); }
template <class Ar> void fields(Ar& ar, PrepassResult& r) {
  ar("stages", r.stages); ar("zones", r.zones); ar("state", r.state); ar("centroid", r.centroid);
  ar("stress", r.stress); ar("gridpoint_u", r.gridpoint_u); ar("seconds", r.seconds);
}

// Everything in Mechanics but the Lua functions (callbacks, histories' samplers, the judge
// criterion, the replayed commands), the run's own settings (threads, progress) and the split
// among threads.
template <class Ar> void fields(Ar& ar, Mechanics& m) {
  ar("materials", m.materials); ar("params", m.params); ar("settings", m.settings); ar("gravity", m.gravity);
  ar("gravity_set", m.gravity_set); ar("insitu", m.insitu); ar("insitu_regions", m.insitu_regions);
  ar("joint_materials", m.joint_materials); ar("joint_params", m.joint_params); ar("jassign", m.jassign);
  ar("jassign_regions", m.jassign_regions); ar("jassign_material", m.jassign_material);
  // state per zone, per node
  ar("zone_material", m.zone_material); ar("stress", m.stress); ar("mean_stress_ref", m.mean_stress_ref);
  ar("zone_state", m.zone_state);
  optional_member(ar, "zone_history", m.zone_history, {});  // older files: none; zeros (check_sizes)
  optional_member(ar, "zone_plastic_work", m.zone_plastic_work, {});  // as zone_history
  ar("node_count", m.node_count); ar("gp_node", m.gp_node);
  ar("position", m.position); ar("u", m.u); ar("v", m.v); ar("origin", m.origin); ar("force", m.force);
  ar("load", m.load); ar("fix", m.fix); ar("node_block", m.node_block); ar("boundary", m.boundary);
  // contacts, potential cracks, excavation, bolts
  ar("faces", m.faces); ar("contacts", m.contacts); ar("crack_seeds", m.crack_seeds); ar("sections", m.sections);
  ar("edge_section", m.edge_section); ar("edge_glued", m.edge_glued); ar("cracks", m.cracks);
  ar("judge_every", m.judge.every); ar("stage", m.stage); ar("zone_excavated", m.zone_excavated);
  optional_member(ar, "stage_cycles", m.stage_cycles, {});  // older files: none (charts mark no stages)
  ar("release", m.release); ar("bolt_materials", m.bolt_materials); ar("bolts", m.bolts);
  ar("bolt_hosts", m.bolt_hosts); ar("fresh_cracks", m.fresh_cracks);
  // derived by prepare()
  ar("fits", m.fits); ar("keep_fits", m.keep_fits); ar("dirty", m.dirty); ar("geometry", m.geometry);
  // Optional: schema-1 files written before it existed have none (their next cycle restarted
  // the damping only if the model was dirty).
  optional_member(ar, "restart_damping", m.restart_damping, false);
  ar("active", m.active); ar("block_live", m.block_live); ar("mates", m.mates); ar("mass", m.mass);
  ar("zone_rows", m.zone_rows); ar("real_mass", m.real_mass); ar("stiffness", m.stiffness); ar("weight", m.weight);
  ar("step", m.step); ar("critical_step", m.critical_step); ar("applied_magnitude", m.applied_magnitude);
  // solver progress
  ar("info", m.info); ar("cycles_run", m.cycles_run); ar("adaptive", m.adaptive); ar("last_kinetic", m.last_kinetic);
  ar("growth_checks", m.growth_checks); ar("growth_span", m.growth_span); ar("next_handle", m.next_handle);
  ar("histories", m.histories);
  optional_member(ar, "judge_most", m.judge.most, 0L);  // files older than judge{ most } have none
  optional_member(ar, "judge_radius", m.judge.radius, 0.0);  // nor older than judge{ radius }
  optional_member(ar, "judge_at", m.judge.at, JudgeAt::cycles);  // nor older than judge{ at }
  // Nor older than judge{ neighbours }: those broke all that failed.
  optional_member(ar, "judge_neighbours_wait", m.judge.neighbours_wait, false);
  // Nor older than the energy balance: theirs starts again at the next cycle.
  optional_member(ar, "energy", m.energy, EnergyLedger{});
}

// ---- The blocks and the mesh hold vectors of vectors per block: stored flat, with offsets, so
// that a model of thousands of blocks is a few datasets and not thousands of groups.

struct FlatBlocks {
  std::vector<std::vector<Vec2>> ring_points;  // per ring: each block's outer ring, then its holes
  std::vector<std::vector<EdgeOrigin>> ring_edges;
  std::vector<int> first_ring;  // per block + 1
  std::vector<double> area;
  std::vector<Vec2> centroid;
  std::vector<int> base;
  std::vector<std::vector<int>> regions;
  int dropped_cuts = 0, joint_edges = 0, snapped_vertices = 0;
  std::optional<int> cuts_left_out;  // optional: schema-1 files written before it existed have none
  std::optional<int> cuts_cut_back;  // the same
  std::optional<int> slivers_kept;   // the same
};
template <class Ar> void fields(Ar& ar, FlatBlocks& b) {
  ar("ring_points", b.ring_points); ar("ring_edges", b.ring_edges); ar("first_ring", b.first_ring);
  ar("area", b.area); ar("centroid", b.centroid); ar("base", b.base); ar("regions", b.regions);
  ar("dropped_cuts", b.dropped_cuts); ar("joint_edges", b.joint_edges); ar("snapped_vertices", b.snapped_vertices);
  ar("cuts_left_out", b.cuts_left_out); ar("cuts_cut_back", b.cuts_cut_back); ar("slivers_kept", b.slivers_kept);
}

struct FlatMesh {
  std::vector<Vec2> gp_position;
  std::vector<int> gp_block;
  std::vector<std::array<int, 3>> zone_gp;
  std::vector<int> zone_block, block_first_gp, block_first_zone;
  std::vector<std::vector<int>> loop_gridpoints;  // per loop: each block's outer loop, then its holes
  std::vector<std::vector<EdgeOrigin>> loop_edges;
  std::vector<int> first_loop;  // per block + 1
};
template <class Ar> void fields(Ar& ar, FlatMesh& m) {
  ar("gp_position", m.gp_position); ar("gp_block", m.gp_block); ar("zone_gp", m.zone_gp);
  ar("zone_block", m.zone_block); ar("block_first_gp", m.block_first_gp); ar("block_first_zone", m.block_first_zone);
  ar("loop_gridpoints", m.loop_gridpoints); ar("loop_edges", m.loop_edges); ar("first_loop", m.first_loop);
}

namespace {

FlatBlocks flatten(const BlockSet& set) {
  FlatBlocks f;
  f.first_ring.push_back(0);
  const auto add_ring = [&](const Ring& r) {
    f.ring_points.push_back(r.points);
    f.ring_edges.push_back(r.edges);
  };
  for (const Block& b : set.blocks) {
    add_ring(b.outer);
    for (const Ring& hole : b.holes) add_ring(hole);
    f.first_ring.push_back(static_cast<int>(f.ring_points.size()));
    f.area.push_back(b.area);
    f.centroid.push_back(b.centroid);
    f.base.push_back(b.base);
    f.regions.push_back(b.regions);
  }
  f.dropped_cuts = set.dropped_cuts;
  f.joint_edges = set.joint_edges;
  f.snapped_vertices = set.snapped_vertices;
  f.cuts_left_out = set.cuts_left_out;
  f.cuts_cut_back = set.cuts_cut_back;
  f.slivers_kept = set.slivers_kept;
  return f;
}

// Throws unless `first` is a list of offsets, from 0 and not decreasing, that ends at `total`.
void check_offsets(const std::vector<int>& first, size_t total, std::string_view what) {
  bool ok = !first.empty() && first.front() == 0 && first.back() == static_cast<int>(total);
  for (size_t i = 1; ok && i < first.size(); ++i) ok = first[i] >= first[i - 1];
  if (!ok) fail("its {} offsets do not match", what);
}

BlockSet unflatten(FlatBlocks f) {
  const size_t n = f.area.size();
  if (f.first_ring.size() != n + 1 || f.centroid.size() != n || f.base.size() != n || f.regions.size() != n ||
      f.ring_edges.size() != f.ring_points.size())
    fail("its blocks are inconsistent");
  check_offsets(f.first_ring, f.ring_points.size(), "block ring");
  BlockSet set;
  set.blocks.resize(n);
  for (size_t i = 0; i < n; ++i) {
    Block& b = set.blocks[i];
    const auto ring = [&](size_t r) { return Ring{std::move(f.ring_points[r]), std::move(f.ring_edges[r])}; };
    const auto begin = static_cast<size_t>(f.first_ring[i]), end = static_cast<size_t>(f.first_ring[i + 1]);
    if (begin == end) fail("block {} has no outline", i + 1);
    b.outer = ring(begin);
    for (size_t r = begin + 1; r < end; ++r) b.holes.push_back(ring(r));
    b.area = f.area[i];
    b.centroid = f.centroid[i];
    b.base = f.base[i];
    b.regions = std::move(f.regions[i]);
  }
  set.dropped_cuts = f.dropped_cuts;
  set.joint_edges = f.joint_edges;
  set.snapped_vertices = f.snapped_vertices;
  set.cuts_left_out = f.cuts_left_out.value_or(0);
  set.cuts_cut_back = f.cuts_cut_back.value_or(0);
  set.slivers_kept = f.slivers_kept.value_or(0);
  return set;
}

FlatMesh flatten(const Mesh& mesh) {
  FlatMesh f{mesh.gp_position, mesh.gp_block,       mesh.zone_gp, mesh.zone_block, mesh.block_first_gp,
             mesh.block_first_zone, {}, {}, {0}};
  for (const auto& loops : mesh.block_boundary) {
    for (const BoundaryLoop& loop : loops) {
      f.loop_gridpoints.push_back(loop.gridpoints);
      f.loop_edges.push_back(loop.edges);
    }
    f.first_loop.push_back(static_cast<int>(f.loop_gridpoints.size()));
  }
  return f;
}

Mesh unflatten(FlatMesh f) {
  Mesh mesh;
  const size_t gps = f.gp_position.size(), zones = f.zone_gp.size(), blocks = f.first_loop.size() - 1;
  if (f.first_loop.empty() || f.gp_block.size() != gps || f.zone_block.size() != zones ||
      f.block_first_gp.size() != blocks + 1 || f.block_first_zone.size() != blocks + 1 ||
      f.loop_edges.size() != f.loop_gridpoints.size())
    fail("its mesh is inconsistent");
  check_offsets(f.first_loop, f.loop_gridpoints.size(), "boundary loop");
  check_offsets(f.block_first_gp, gps, "block gridpoint");
  check_offsets(f.block_first_zone, zones, "block zone");
  const auto gridpoint = [&](int g) { return g >= 0 && static_cast<size_t>(g) < gps; };
  for (const auto& corners : f.zone_gp)
    for (int g : corners)
      if (!gridpoint(g)) fail("a zone of its mesh has a gridpoint out of range ({})", g);
  for (const auto& loop : f.loop_gridpoints)
    for (int g : loop)
      if (!gridpoint(g)) fail("a boundary loop of its mesh has a gridpoint out of range ({})", g);
  for (const auto* owners : {&f.gp_block, &f.zone_block})
    for (int b : *owners)
      if (b < 0 || static_cast<size_t>(b) >= blocks) fail("its mesh refers to block {}, out of range", b);
  mesh.block_boundary.resize(blocks);
  for (size_t b = 0; b < blocks; ++b)
    for (auto l = static_cast<size_t>(f.first_loop[b]); l < static_cast<size_t>(f.first_loop[b + 1]); ++l)
      mesh.block_boundary[b].push_back({std::move(f.loop_gridpoints[l]), std::move(f.loop_edges[l])});
  mesh.gp_position = std::move(f.gp_position);
  mesh.gp_block = std::move(f.gp_block);
  mesh.zone_gp = std::move(f.zone_gp);
  mesh.zone_block = std::move(f.zone_block);
  mesh.block_first_gp = std::move(f.block_first_gp);
  mesh.block_first_zone = std::move(f.block_first_zone);
  return mesh;
}

// Every entry of `values` in [low, count); `what` names them in the message.
void check_range(const std::vector<int>& values, int low, size_t count, std::string_view what) {
  for (const int v : values)
    if (v < low || (v >= 0 && static_cast<size_t>(v) >= count)) fail("its {} refer to {}, out of range", what, v);
}

// Offsets into an array of `total` entries: one per item + 1, from 0, not decreasing.
void check_first(const std::vector<int>& first, size_t items, size_t total, std::string_view what) {
  if (first.empty() && items == 0) return;
  if (first.size() != items + 1) fail("its {} offsets are {}, for {} items", what, first.size(), items);
  check_offsets(first, total, what);
}

// The indices a cycle or a query follows: a file that passed its checksum fails these only when
// it was altered and its checksum forged, but then with a message rather than a crash.
void check_indices(const Mechanics& m, const Mesh& mesh) {
  const size_t nodes = static_cast<size_t>(m.node_count), zones = static_cast<size_t>(mesh.zone_count());
  const size_t blocks = mesh.block_boundary.size(), edges = m.faces.edges.size();
  std::vector<int> ends, links, edge_blocks, contact_nodes, contact_edges, contact_blocks, materials;
  for (const ContactEdge& e : m.faces.edges) {
    ends.insert(ends.end(), {e.a, e.b});
    links.insert(links.end(), {e.prev, e.next});
    edge_blocks.push_back(e.block);
    materials.push_back(e.material);
  }
  check_range(ends, 0, nodes, "contact edges' nodes");
  check_range(links, -1, edges, "contact edges' neighbours");
  check_range(edge_blocks, 0, blocks, "contact edges' blocks");
  check_range(materials, -1, m.joint_materials.size(), "contact edges' joint materials");
  check_first(m.faces.block_first_edge, blocks, edges, "block edge");
  check_range(m.faces.nodes, 0, nodes, "contact nodes");
  check_first(m.faces.edge_first, m.faces.nodes.size(), m.faces.node_edges.size(), "node edge");
  check_range(m.faces.node_edges, 0, edges, "node edges");
  check_first(m.faces.block_first, m.faces.nodes.size(), m.faces.node_blocks.size(), "node block");
  check_range(m.faces.node_blocks, 0, blocks, "node blocks");
  if (m.faces.reach.size() != m.faces.nodes.size() && !m.faces.reach.empty()) fail("its contact reaches do not match");
  materials.clear();
  for (const Contact& c : m.contacts.list) {
    contact_nodes.push_back(c.node);
    for (const int far : {c.far_a, c.far_b})
      if (far >= 0 || c.per_facing > 0.0) contact_nodes.push_back(far);
    contact_edges.push_back(c.edge);
    contact_blocks.insert(contact_blocks.end(), {c.block, c.other});
    materials.push_back(c.material);
  }
  check_range(contact_nodes, 0, nodes, "contacts' nodes");
  check_range(contact_edges, 0, edges, "contacts' edges");
  check_range(contact_blocks, 0, blocks, "contacts' blocks");
  check_range(materials, 0, m.joint_materials.size(), "contacts' joint materials");
  std::vector<int> section_gps, section_edges, section_blocks;
  for (const Section& s : m.sections) {
    section_gps.insert(section_gps.end(), {s.a[0], s.a[1], s.b[0], s.b[1]});
    section_edges.insert(section_edges.end(), {s.edge[0], s.edge[1]});
    section_blocks.insert(section_blocks.end(), {s.block[0], s.block[1]});
  }
  check_range(section_gps, -1, static_cast<size_t>(mesh.gp_count()), "sections' gridpoints");
  check_range(section_blocks, -1, blocks, "sections' blocks");
  check_range(m.edge_section, -1, m.sections.size(), "edges' sections");
  check_range(section_edges, -1, m.edge_section.size(), "sections' edges");
  if (m.edge_glued.size() != m.edge_section.size()) fail("its loop edges do not match");
  for (size_t s = 0; s < m.sections.size(); ++s)
    for (const int e : m.sections[s].edge)
      if (e >= 0 && m.edge_section[static_cast<size_t>(e)] != static_cast<int>(s))
        fail("its section {} and loop edge {} disagree", s, e);
  if (!m.fits.first.empty()) check_first(m.fits.first, m.sections.size(), m.fits.zone.size(), "section fit");
  check_range(m.fits.zone, 0, zones, "section fits' zones");
  check_range(m.fits.after, -1, m.joint_materials.size(), "sections' joint materials once broken");
  std::vector<int> seeds;
  for (const Section& s : m.sections) seeds.push_back(s.seed);
  check_range(seeds, -1, m.crack_seeds.size(), "sections' crack seeds");
  std::vector<int> crack_sections;
  for (const CrackView& c : m.cracks) crack_sections.push_back(c.section);
  check_range(crack_sections, 0, m.sections.size(), "cracks' sections");
  std::vector<int> corners;
  for (const ZoneGeometry& g : m.geometry) corners.insert(corners.end(), g.node.begin(), g.node.end());
  check_range(corners, 0, nodes, "zones' nodes");
  check_range(m.active, 0, zones, "active zones");
  check_range(m.zone_material, -1, m.materials.size(), "zones' materials");
  check_range(m.bolts.segments.a, 0, m.bolts.nodes.size(), "bolt segments' nodes");
  check_range(m.bolts.segments.b, 0, m.bolts.nodes.size(), "bolt segments' nodes");
  check_range(m.bolts.segments.material, 0, m.bolts.laws.size(), "bolt segments' materials");
  check_first(m.bolts.bolt_first_node, m.bolt_hosts.material.size(), m.bolts.nodes.size(), "bolt node");
  check_first(m.bolts.bolt_first_segment, m.bolt_hosts.material.size(), m.bolts.segments.size(), "bolt segment");
  check_range(m.bolt_hosts.zone, -1, zones, "bolt hosts' zones");
  check_range(m.bolt_hosts.material, 0, m.bolt_materials.size(), "bolts' materials");
}

// The bolts' arrays: each per bolt node, per segment or per bolt as long as the others of its kind.
template <class Expect>
void check_bolt_sizes(const Mechanics& m, size_t nodes, const Expect& expect) {
  const BoltNodes& n = m.bolts.nodes;
  const size_t bolt_nodes = n.x.size();
  for (const auto& [got, what] : std::initializer_list<std::pair<size_t, std::string_view>>{
           {n.u.size(), "bolt nodes' u"}, {n.v.size(), "bolt nodes' v"}, {n.force.size(), "bolt nodes' force"},
           {n.mass.size(), "bolt nodes' mass"}, {n.tributary.size(), "bolt nodes' tributary"},
           {n.bond_length.size(), "bolt nodes' bond_length"}, {n.grout_stiffness.size(), "bolt nodes' grout_stiffness"},
           {n.grout_strength.size(), "bolt nodes' grout_strength"}, {n.axis.size(), "bolt nodes' axis"},
           {n.grout_force.size(), "bolt nodes' grout_force"}, {n.grout_slip.size(), "bolt nodes' grout_slip"},
           {n.slipping.size(), "bolt nodes' slipping"}, {n.grout_rel.size(), "bolt nodes' grout_rel"}})
    expect(got, bolt_nodes, what);
  const BoltSegments& g = m.bolts.segments;
  for (const auto& [got, what] : std::initializer_list<std::pair<size_t, std::string_view>>{
           {g.b.size(), "bolt segments' b"}, {g.material.size(), "bolt segments' material"},
           {g.rest.size(), "bolt segments' rest"}, {g.elongation.size(), "bolt segments' elongation"},
           {g.direction.size(), "bolt segments' direction"}, {g.force.size(), "bolt segments' force"},
           {g.state.size(), "bolt segments' state"}, {g.broke.size(), "bolt segments' broke"}})
    expect(got, g.size(), what);
  const BoltHosts& h = m.bolt_hosts;
  for (const auto& [got, what] : std::initializer_list<std::pair<size_t, std::string_view>>{
           {h.zone.size(), "bolt hosts' zone"}, {h.weight.size(), "bolt hosts' weight"}, {h.u0.size(), "bolt hosts' u0"},
           {h.host_u.size(), "bolt hosts' host_u"}, {h.slide.size(), "bolt hosts' slide"}, {h.dir.size(), "bolt hosts' dir"},
           {h.rate.size(), "bolt hosts' rate"}, {h.mass.size(), "bolt hosts' mass"}})
    expect(got, bolt_nodes, what);
  // Adaptive damping's start goes with the bolt nodes it was taken on: a bolt laid since leaves it
  // short until the next cycle takes it again (bolt_cycle).
  expect(h.r_start.size(), h.slide_start.size(), "bolt hosts' r_start");
  const size_t bolts = h.material.size();
  for (const auto& [got, what] : std::initializer_list<std::pair<size_t, std::string_view>>{
           {h.stage.size(), "bolts' stage"}, {h.removed.size(), "bolts' removed"}, {h.drive.size(), "bolts' drive"},
           {h.drive_value.size(), "bolts' drive_value"}, {h.head_force.size(), "bolts' head_force"}})
    expect(got, bolts, what);
  expect(m.bolts.bolt_first_node.size(), bolts + 1, "bolts' first nodes");
  expect(m.bolts.bolt_first_segment.size(), bolts + 1, "bolts' first segments");
  if (!m.dirty) {  // derived when the model is prepared: a dirty model makes them again
    expect(h.gather_first.size(), nodes + 1, "bolt hosts' gather_first");
    expect(h.rows.size(), nodes, "bolt hosts' rows");
    check_first(h.gather_first, nodes, h.gather.size(), "bolt grout gather");
    check_range(h.gather, 0, 3 * bolt_nodes, "bolt grout gathers' corners");
  }
}

// Array lengths that must agree with the mesh and the node count; a file that passed its checksum
// only fails these if an EDEM of the same schema wrote something else, but then the message is
// better than a crash.
void check_sizes(const Mechanics& m, const Mesh& mesh) {
  const size_t zones = static_cast<size_t>(mesh.zone_count()), nodes = static_cast<size_t>(m.node_count);
  const auto expect = [](size_t got, size_t want, std::string_view what) {
    if (got != want) fail("its {} has {} entries where {} belong", what, got, want);
  };
  expect(m.zone_material.size(), zones, "zone_material");
  expect(m.stress.size(), zones, "stress");
  expect(m.zone_state.size(), zones, "zone_state");
  expect(m.zone_history.size(), zones, "zone_history");
  expect(m.zone_plastic_work.size(), zones, "zone_plastic_work");
  expect(m.zone_excavated.size(), zones, "zone_excavated");
  expect(m.gp_node.size(), static_cast<size_t>(mesh.gp_count()), "gp_node");
  for (const auto* v : {&m.position, &m.u, &m.v, &m.origin, &m.force, &m.load}) expect(v->size(), 2 * nodes, "node vector");
  expect(m.fix.size(), nodes, "fix");
  check_bolt_sizes(m, nodes, expect);
  // Arrays made when the model is prepared, its contacts found or its damping started: whole once
  // they have been (a prepared model is not prepared again: it would read past them).
  const auto expect_if = [&](bool made, size_t got, size_t want, std::string_view what) {
    if (made) expect(got, want, what);  // else stale or empty: made again before they are used
  };
  const bool prepared = !m.dirty;
  // (The damping's start goes with the nodes it was taken on; the next batch takes it again if
  // they have changed since.)
  expect(m.adaptive.r_start.size(), m.adaptive.u_start.size(), "adaptive damping's r_start");
  expect_if(prepared, m.block_live.size(), mesh.block_boundary.size(), "block_live");
  expect_if(prepared, m.weight.size(), 2 * nodes, "weight");
  expect_if(prepared, m.real_mass.size(), nodes, "real_mass");
  expect_if(prepared, m.stiffness.size(), nodes, "stiffness");
  expect_if(prepared, m.zone_rows.size(), nodes, "zone_rows");
  const bool contacts_current = prepared && m.contacts.detected;
  expect_if(contacts_current, m.contacts.x_detected.size(), 2 * nodes, "contacts' x_detected");
  expect_if(contacts_current, m.contacts.rows.size(), nodes, "contacts' rows");
  if (contacts_current) {
    expect(m.contacts.gather_first.size(), nodes + 1, "contacts' gather_first");
    check_first(m.contacts.gather_first, nodes, m.contacts.gather.size(), "contact gather");
    check_range(m.contacts.gather, 0, kContactRoles * m.contacts.list.size(), "contact gathers' forces");
  }
  expect(m.node_block.size(), nodes, "node_block");
  if (!m.dirty) {
    expect(m.geometry.size(), zones, "geometry");
    expect(m.mass.size(), nodes, "mass");
  }
  expect(m.params.size(), m.materials.size(), "params");
  expect(m.jassign_regions.size(), m.jassign_material.size(), "jassign_regions");
  expect_if(!m.mean_stress_ref.empty(), m.mean_stress_ref.size(), zones, "mean_stress_ref");
  expect(m.joint_params.size(), m.joint_materials.size(), "joint_params");
  for (int material : m.zone_material)
    if (material >= static_cast<int>(m.materials.size())) fail("a zone's material {} is out of range", material);
  for (int node : m.gp_node)
    if (node < 0 || static_cast<size_t>(node) >= nodes) fail("a gridpoint's node {} is out of range", node);
  for (const Contact& c : m.contacts.list)
    if (c.node < 0 || static_cast<size_t>(c.node) >= nodes || c.edge < 0 ||
        static_cast<size_t>(c.edge) >= m.faces.edges.size())
      fail("a contact refers to node {} or edge {}, out of range", c.node, c.edge);
  for (const MaterialParams& p : m.params)
    if (static_cast<size_t>(p.model) >= zone_laws().size()) fail("a material's model {} is unknown", static_cast<int>(p.model));
  if (prepared) {  // the zones that cycle: every zone of rock not dug out, in order
    size_t live = 0;
    for (size_t z = 0; z < zones; ++z) {
      const int material = m.zone_material[z];
      live += material >= 0 && m.zone_excavated[z] == 0 &&
              !zone_law(m.params[static_cast<size_t>(material)].model).is_void;
    }
    expect(m.active.size(), live, "active zones");
    for (size_t i = 1; i < m.active.size(); ++i)
      if (m.active[i] <= m.active[i - 1]) fail("its active zones are out of order");
  }
}

std::string local_time_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &tm);
  return text;
}

}  // namespace

// Model's private members, for save and restore only.
struct CheckpointAccess {
  template <class Ar>
  static void inputs(Ar& ar, Model& model) {
    auto& in = model.inputs_;
    ar("bases", in.bases);
    ar("joint_sets", in.joint_sets);
    ar("cracks", in.cracks);
    ar("crack_seeds", in.crack_seeds);
    ar("regions", in.regions);
    for (const BlockDef& b : in.bases)
      if (b.polygon.size() < 3) fail("a block's outline has {} corners", b.polygon.size());
    for (const RegionDef& region : in.regions)
      if (region.polygon.size() < 3) fail("region '{}' has {} corners", region.name, region.polygon.size());
    std::int64_t requests = static_cast<std::int64_t>(in.zone_requests.size());
    ar("zone_requests", requests);
    if (requests < 0 || requests > 1'000'000) fail("it has {} zone requests", requests);
    in.zone_requests.resize(static_cast<size_t>(requests));
    for (size_t i = 0; i < in.zone_requests.size(); ++i) {
      auto& r = in.zone_requests[i];
      ar(fmt::format("zone_request_{}_size", i).c_str(), r.size);
      ar(fmt::format("zone_request_{}_region", i).c_str(), r.region);
      ar(fmt::format("zone_request_{}_polygon", i).c_str(), r.polygon);
      // Files older than zone{ sliver } have none: their blocks were cut without it.
      optional_member(ar, fmt::format("zone_request_{}_sliver", i).c_str(), r.sliver, 0.0);
    }
  }

  static void save(const Model& model, const std::string& path, const CheckpointNote& note) {
    const Mechanics& m = *model.mechanics_;
    write_checkpoint(path, [&](hid_t file) {
      h5::Writer root(file, "");
      auto& mutable_model = const_cast<Model&>(model);  // the archive's field lists take non-const refs
      {
        const h5::Handle group = root.group("note");
        h5::Writer w(group.get(), "/note");
        CheckpointNote n = note;
        n.edem_version = EDEM_VERSION;
        if (n.saved_at.empty()) n.saved_at = local_time_now();
        w("script_path", n.script_path);
        w("script", n.script);
        w("saved_at", n.saved_at);
        w("edem_version", n.edem_version);
        w("callbacks", static_cast<std::int64_t>(m.callbacks.size()));
        w("judge_criterion", static_cast<bool>(m.judge.criterion) || m.judge_criterion_missing);
      }
      const h5::Handle group = root.group("model");
      h5::Writer w(group.get(), "/model");
      w("title", model.def_.title);
      w("tolerance", model.def_.tolerance);
      {
        const h5::Handle g = w.group("inputs");
        h5::Writer in(g.get(), w.at("inputs"));
        inputs(in, mutable_model);
      }
      w("blocks", flatten(model.blocks_));
      w("mesh", flatten(model.mesh_));
      w("mechanics", *model.mechanics_);
      w("prepass_yield", model.prepass_yield_);
      w("last_prepass", model.last_prepass_);
    });
  }

  static Model restore(const std::string& path, CheckpointNote* note_out) {
    CheckpointFile file = open_checkpoint(path);
    const h5::QuietErrors quiet;
    try {
      h5::Reader root(file.file.get(), "");
      CheckpointNote note;
      bool judge_criterion = false;
      {
        const h5::Handle group = root.group("note");
        h5::Reader r(group.get(), "/note");
        r("script_path", note.script_path);
        r("script", note.script);
        r("saved_at", note.saved_at);
        r("edem_version", note.edem_version);
        r("judge_criterion", judge_criterion);
      }
      const h5::Handle group = root.group("model");
      h5::Reader r(group.get(), "/model");
      ModelDef def;
      r("title", def.title);
      r("tolerance", def.tolerance);
      Model model(def);
      {
        const h5::Handle g = r.group("inputs");
        h5::Reader in(g.get(), r.at("inputs"));
        inputs(in, model);
      }
      FlatBlocks blocks;
      r("blocks", blocks);
      model.blocks_ = unflatten(std::move(blocks));
      FlatMesh mesh;
      r("mesh", mesh);
      model.mesh_ = unflatten(std::move(mesh));
      Mechanics& m = *model.mechanics_;
      r("mechanics", m);
      if (m.zone_history.empty()) m.zone_history.assign(m.zone_state.size(), 0.0);
      if (m.zone_plastic_work.empty()) m.zone_plastic_work.assign(m.zone_state.size(), 0.0);
      check_sizes(m, model.mesh_);
      check_indices(m, model.mesh_);
      if (!(m.faces.median_edge > 0.0)) m.faces.median_edge = median_edge_length(m.faces, m.position);
      for (size_t j = 0; j < m.joint_params.size(); ++j)
        if (m.joint_params[j].curve_closure < 0.0)
          m.joint_params[j].curve_closure = joint_params(m.joint_materials[j]).curve_closure;
      // The gather follows from the contacts and the faces: made anew, whatever the file holds.
      if (m.contacts.detected) gather_contact_forces(m.contacts, m.faces, m.node_count);
      mark_glued_tips(m.faces, m.position);
      r("prepass_yield", model.prepass_yield_);
      r("last_prepass", model.last_prepass_);
      m.judge_criterion_missing = judge_criterion;
      for (History& h : m.histories)
        if (!h.quantity.empty()) model.follow(h);
      model.restored_ = true;
      if (note_out != nullptr) *note_out = std::move(note);
      return model;
    } catch (const Error& e) {
      fail("cannot restore '{}': {}", path, e.what());
    } catch (const std::bad_alloc&) {
      fail("cannot restore '{}': it asks for more memory than there is (is it damaged?)", path);
    }
  }
};

void Model::save(const std::string& path, const CheckpointNote& note) const { CheckpointAccess::save(*this, path, note); }

Model Model::restore(const std::string& path, CheckpointNote* note) { return CheckpointAccess::restore(path, note); }

}  // namespace edem
