// Excavation: excavate{} turns a region's zones null, fill{} puts material back, stage() counts.
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

// A region given as item 1 (a name) or as region = (a name or a polygon); not both, not neither.
RegionRef region_of(const Args& args, const char* usage) {
  const bool item = args.has("name"), key = args.has("region");
  if (item == key)
    fail("{}: give the region as item 1 or as region =, like {}", item ? "both given" : "no region", usage);
  if (item) return RegionRef{args.string("name"), {}};
  return args.get<RegionRef>("region");
}

int run_excavate(lua_State*, Context& context, const Args& args) {
  ExcavateDef def;
  if (args.has("block")) {
    if (args.has("name") || args.has("region")) fail("give a region or a block, not both");
    def.block = static_cast<int>(args.integer("block")) - 1;
  } else {
    def.region = region_of(args, "excavate(\"stage1\")");
  }
  def.release = static_cast<long>(args.integer("release"));
  if (def.block < 0) context.write_stage_frames();  // the state the stage reached (not for mucking out a block)
  context.model().excavate(def);
  return 0;
}

int run_fill(lua_State*, Context& context, const Args& args) {
  FillDef def;
  def.region = region_of(args, "fill{ \"stage1\", material = \"concrete\" }");
  def.material = args.string("material");
  context.model().fill(def);
  return 0;
}

int run_stage(lua_State* L, Context& context, const Args&) {
  lua_pushinteger(L, context.model().stage());
  return 1;
}

// The region of excavate{} and fill{}: item 1 (a name) or region = (a name or a polygon).
const Key kRegionItem{"name", Type::string, "", any_value, kOptional, "a region's name", "or region"};
const Key kRegionKey{"region", Type::region, "", any_value, kOptional, "the region (a name or a polygon)",
                     "or item 1"};

}  // namespace

const Command& excavate_command() {
  static const Command command{
      .name = "excavate",
      .help =
          "Excavates a region: its zones turn null, as in UDEC 7 (the geometry stays: fill{} "
          "can put material back), the new surface is free and contacts with the excavated "
          "blocks go; the stage count (stage()) goes up by one and cracks and histories carry "
          "it. With release = n, what the excavation takes off the rock in place is held on it "
          "as a load and taken off linearly over the next n cycles, so that the rock unloads "
          "gradually instead of ringing: the excavated zones' pull (their stress and weight) "
          "and the push of the excavated blocks' contacts, on the new surface and on the rock "
          "they pressed across joints (the contacts are found again at once for it; bolts cut "
          "by the excavation let go at once); solve{} does not stop before it is off. The "
          "region must take whole blocks: a name cut earlier with region{}, or a polygon along "
          "block outlines. assign{} later changes excavated zones' material without filling them. "
          "excavate{ block = id } takes out one block wherever it is now, as a fallen block is "
          "mucked out (UDEC's delete); that is no new stage.",
      .positional = {kRegionItem},
      .keys =
          {
              kRegionKey,
              {"block", Type::integer, "", ge(1), kOptional,
               "or a block's id (blocks()): a loose block taken out wherever it has moved to", "a region"},
              {"release", Type::integer, "cycles", ge(0), "0",
               "cycles over which the excavated rock's forces come off the rock in place (0: at once)"},
          },
      .run = run_excavate,
      .usage = "excavate(\"stage1\")\nexcavate{ region = \"stage2\", release = 2000 }",
      .item_call = true,
  };
  return command;
}

const Command& fill_command() {
  static const Command command{
      .name = "fill",
      .help =
          "Backfills the excavated zones of a region with a material, stress-free (they take "
          "load as the rock around them moves on).",
      .positional = {kRegionItem},
      .keys =
          {
              kRegionKey,
              {"material", Type::string, "", any_value, kRequired, "a material's name"},
          },
      .run = run_fill,
      .usage = "fill{ \"stage1\", material = \"concrete\" }",
  };
  return command;
}

const Command& stage_command() {
  static const Command command{
      .name = "stage",
      .help = "The excavation stage: how many excavate{} calls so far (0 before any).",
      .form = Form::call,
      .run = run_stage,
      .returns = "an integer",
      .usage = "if stage() == 3 then ... end",
  };
  return command;
}

}  // namespace edem
