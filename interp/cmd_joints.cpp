// Joint materials: joint_material{} defines one, jassign{} gives it to the contacts along
// joints, cracks and block outlines.
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

const std::vector<std::string>& normal_laws() {
  static const std::vector<std::string> names = {"seed-cubic"};
  return names;
}

const std::vector<std::string>& contact_kinds() {
  static const std::vector<std::string> names = {"joint", "crack", "glued"};
  return names;
}

int run_joint_material(lua_State*, Context& context, const Args& args) {
  JointMaterialDef def;
  def.name = args.string("name");
  if (def.name.empty()) fail("name must not be empty");
  const int laws = args.has("kn") + args.has("kn_table") + args.has("kn_law");
  if (laws == 0) fail("give the normal stiffness: kn, kn_table or kn_law");
  if (laws > 1) fail("give one of kn, kn_table and kn_law, not several");
  if (args.has("kn")) def.kn = args.number("kn");
  if (args.has("kn_table")) {
    def.law = NormalLaw::table;
    def.kn_table = args.get<std::vector<std::array<double, 2>>>("kn_table");
  }
  if (args.has("kn_law")) def.law = NormalLaw::seed_cubic;
  if ((args.has("stress_scale") || args.has("closure_scale")) && !args.has("kn_law"))
    fail("stress_scale and closure_scale scale kn_law's curve: give kn_law, or leave them out");
  if (args.has("stress_scale")) def.law_stress_scale = args.number("stress_scale");
  if (args.has("closure_scale")) def.law_closure_scale = args.number("closure_scale");
  def.ks = args.number("ks");
  def.friction = args.number("friction");
  def.cohesion = args.number("cohesion");
  def.tension = args.number("tension");
  def.dilation = args.number("dilation");
  def.residual_cohesion = args.number("residual_cohesion");
  if (args.has("residual_friction")) def.residual_friction = args.number("residual_friction");
  def.fracture_energy = args.number("fracture_energy");
  def.shear_fracture_energy = args.number("shear_fracture_energy");
  context.model().add_joint_material(def);
  return 0;
}

int run_jassign(lua_State*, Context& context, const Args& args) {
  JassignDef def;
  def.material = args.string("material");
  if (args.has("set")) def.set = static_cast<int>(args.integer("set")) - 1;
  if (args.has("kind")) def.kind = args.string("kind");
  if (args.has("region")) def.region = args.get<RegionRef>("region");
  context.model().jassign(def);
  return 0;
}

}  // namespace

const Command& joint_material_command() {
  static const Command command{
      .name = "joint_material",
      .help =
          "Defines a joint material: the law of the contacts along joints and cracks. Normal "
          "stress from closure by one of: a constant kn; kn_table, stages {closure from, kn} "
          "(closures from 0, increasing); or kn_law = \"seed-cubic\", the seed paper's lab "
          "curve sn = -4.302 v^3 + 7.688 v^2 - 0.123 v (MPa, mm), started at its zero "
          "crossing and straight at 1880 MPa/m past its descending 1880 MPa/m point, so that "
          "it never gives tension or a negative stiffness; stress_scale and closure_scale read "
          "it at another scale, sn = stress_scale f(closure / closure_scale) (a similarity "
          "law: the seed's prototype takes 17.86 and 400). Shear: ks and Coulomb slip; "
          "cohesion and tension hold only until the contact first slips or opens; then it "
          "has no tension and its residual cohesion and friction (UDEC's Coulomb slip with "
          "residual strength; by default zero and the friction; residual_cohesion = cohesion "
          "keeps it). Dilation opens the joint while it slips. With fracture_energy (opening) or "
          "shear_fracture_energy (slip), the bond softens instead of dropping at once, "
          "linearly, as a cohesive crack (Hillerborg): the tensile strength falls to 0 at an "
          "opening of 2 fracture_energy / tension past the elastic one, unloading towards "
          "zero opening; the cohesion falls to residual_cohesion at a plastic slip of 2 "
          "shear_fracture_energy / (cohesion - residual_cohesion), the friction staying at its "
          "peak meanwhile; what is left is the smaller of the two. (A shear_fracture_energy "
          "below cohesion^2 / (2 ks) loses the cohesion faster than the contact unloads: the "
          "slip snaps through.) A potential crack whose "
          "crack takes such a material breaks into a bonded crack, carrying the section's "
          "traction, tension too, at most its peak (a section judged past its strength starts "
          "its crack at the peak, not already softened), until its strength runs out. Defining "
          "a name again replaces that material, in its contacts too.",
      .positional =
          {
              {"name", Type::string, "", any_value, kRequired, "the joint material's name"},
          },
      .keys =
          {
              {"kn", Type::number, "Pa/m", gt(0), kOptional, "normal stiffness",
               "kn_table or kn_law"},
              {"kn_table", Type::pairs, "m, Pa/m", ge(0), kOptional,
               "normal stiffness by stages: {{0, kn1}, {closure2, kn2}, ...}", "kn or kn_law"},
              {"kn_law",
               Type::string,
               "",
               any_value,
               kOptional,
               "a named normal law",
               "kn or kn_table",
               normal_laws},
              {"stress_scale", Type::number, "-", gt(0), kOptional,
               "kn_law's stresses times this (default 1; its stiffnesses times stress_scale / "
               "closure_scale)"},
              {"closure_scale", Type::number, "-", gt(0), kOptional,
               "kn_law's closures times this (default 1)"},
              {"ks", Type::number, "Pa/m", gt(0), kRequired, "shear stiffness"},
              {"friction", Type::number, "deg", from_below(0, 90), "0", "friction angle"},
              {"cohesion", Type::number, "Pa", ge(0), "0", "cohesion, until it first slips or opens"},
              {"tension", Type::number, "Pa", ge(0), "0",
               "tensile strength, until it first slips or opens"},
              {"dilation", Type::number, "deg", ge(0), "0", "dilation angle, at most friction"},
              {"residual_cohesion", Type::number, "Pa", ge(0), "0",
               "cohesion once it has slipped or opened, at most cohesion"},
              {"residual_friction", Type::number, "deg", from_below(0, 90), kOptional,
               "friction angle once it has slipped or opened (default: friction)"},
              {"fracture_energy", Type::number, "J/m^2", ge(0), "0",
               "energy to break the bond in opening: softens the tension (0: drops at once)"},
              {"shear_fracture_energy", Type::number, "J/m^2", ge(0), "0",
               "energy to break the bond in slip: softens the cohesion (0: drops at once)"},
          },
      .run = run_joint_material,
      .usage =
          "joint_material{ \"joint\", kn = 1.2e7, ks = 3.6e6, friction = 31.2 }\n"
          "joint_material{ \"seed\", kn_law = \"seed-cubic\", ks = 8.07e7, friction = 31.2 }\n"
          "joint_material{ \"prototype\", kn_law = \"seed-cubic\", stress_scale = 17.86, "
          "closure_scale = 400, ks = 3.6e6, friction = 31.2 }\n"
          "joint_material{ \"cohesive\", kn = 1.88e9, ks = 1.88e9, friction = 34, "
          "cohesion = 0.143e6, tension = 0.0546e6, fracture_energy = 20, "
          "shear_fracture_energy = 100 }",
  };
  return command;
}

const Command& jassign_command() {
  static const Command command{
      .name = "jassign",
      .help =
          "Gives a joint material to the contacts along edges: all that can touch another "
          "block, or those of a joint set, of a kind (\"joint\": joint sets and the outlines "
          "of separate block{}s; \"crack\": crack{} traces), or with their midpoint in a "
          "region; what is given must all hold. Later assignments win. Region outlines are "
          "glued (one continuum, no contacts). Needs zones: use it after `zone{}`.",
      .keys =
          {
              {"material", Type::string, "", any_value, kRequired, "a joint material's name"},
              {"set", Type::integer, "", ge(1), kOptional, "only this joint set (1 = the first jset{})",
               "all"},
              {"kind",
               Type::string,
               "",
               any_value,
               kOptional,
               "only edges of this kind",
               "all",
               contact_kinds},
              {"region", Type::region, "", any_value, kOptional,
               "only edges whose midpoint is inside this region (a name or a polygon)", "everywhere"},
          },
      .run = run_jassign,
      .usage = "jassign{ material = \"joint\" }\njassign{ material = \"weak\", set = 2, region = \"fault\" }",
  };
  return command;
}

}  // namespace edem
