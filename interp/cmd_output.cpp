// output{}: field output for ParaView, XDMF + HDF5 (engine/io/field_output.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "io/field_output.hpp"

namespace edem {
namespace {

const std::vector<std::string>& output_times() {
  static const std::vector<std::string> times{"stage"};
  return times;
}

int run_output(lua_State* L, Context& context, const Args& args) {
  const std::string file = context.output_path(args.string("file"));
  if (args.has("every") && args.has("at")) fail("give every or at, not both");
  auto found = context.outputs.find(file);
  if (found == context.outputs.end()) found = context.outputs.emplace(file, FieldSeries(file)).first;
  if (args.has("at")) {
    // Before each excavate{} and at the end of the script; asking twice changes nothing.
    if (std::find(context.stage_outputs.begin(), context.stage_outputs.end(), file) == context.stage_outputs.end())
      context.stage_outputs.push_back(file);
    return 0;
  }
  if (!args.has("every")) {
    context.write_frame(file);
    return 0;
  }
  Context* c = &context;
  const int handle = context.model().add_callback(static_cast<long>(args.integer("every")),
                                                  [c, file](long) { c->write_frame(file); });
  lua_pushinteger(L, handle);
  return 1;
}

}  // namespace

const Command& output_command() {
  static const Command command{
      .name = "output",
      .help =
          "Field output for ParaView: frames of the model in FILE's .h5 beside an XDMF index FILE "
          "(open it in "
          "ParaView; its frames are a time series). Each frame holds, at reference positions with a "
          "displacement per point (Warp By Vector on it shows the model now): the zones in "
          "place and their gridpoints (stresses sxx, syy, sxy, szz, s1, s3, plastic state bits, material and block per "
          "zone; "
          "displacement and velocity per gridpoint), the contacts as lines along their planes (fn, "
          "fs, un, us, "
          "slip, state 0 bonded 1 elastic 2 slip 3 open, kind 0 joint 1 crack), the broken "
          "potential-crack "
          "sections (mode 1 shear 2 tension, cycle, stage) and the bolt segments (force, strain, "
          "state 0 "
          "elastic 1 yielded 2 broken 3 removed: its rock gone). Without every or at: one frame "
          "now. The first frame "
          "of a file in a run replaces what was there.",
      .keys =
          {
              {"file", Type::string, "", any_value, kRequired,
               "the XDMF index, .xdmf or .xmf (the data go to the same name in .h5; under --out "
               "when relative)"},
              {"every", Type::integer, "cycles", ge(1), kOptional,
               "a frame after every n-th cycle from now on; returns a handle for cancel()", "none"},
              {"at", Type::string, "", any_value, kOptional,
               "\"stage\": a frame before each excavate{} (the state the stage reached) and at the "
               "end of the "
               "script",
               "none", output_times},
          },
      .run = run_output,
      .returns = "with every: the callback's handle",
      .usage =
          "output{ file = \"cavern.xdmf\", at = \"stage\" }\noutput{ file = \"run.xdmf\", every = "
          "1000 }",
  };
  return command;
}

}  // namespace edem
