// save() and restore(): checkpoints of the whole model (engine/model/checkpoint.cpp).
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <lua.hpp>

#include "checkpoint_summary.hpp"
#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

int run_save(lua_State*, Context& context, const Args& args) {
  const std::string file = context.output_path(args.string("file"));
  const Model& model = context.model();
  model.save(file, {.script_path = context.script_path, .script = context.script_text});
  if (!context.quiet) {
    const SolverInfo info = model.solver_info();
    fmt::print("save: {} (cycle {}, stage {})\n", file, info.cycle, model.stage());
    std::fflush(stdout);
  }
  return 0;
}

int run_restore(lua_State*, Context& context, const Args& args) {
  if (const Running* cycling = context.cycling())
    fail("cannot restore a model inside a callback while {}() at {} cycles the current one", cycling->command,
         cycling->cycling_at);
  const std::string file = context.output_path(args.string("file"));
  CheckpointNote note;
  // Read completely before the current model is dropped, so a bad file keeps it.
  auto restored = std::make_unique<Model>(Model::restore(file, &note));
  const long cycle = restored->solver_info().cycle;
  const int stage = restored->stage();
  context.replace_model(std::move(restored));
  if (!context.quiet) {
    fmt::print("restore: {} (saved {} by EDEM {}{}; cycle {}, stage {})\n", file, note.saved_at, note.edem_version,
               note.script_path.empty() ? "" : " from " + note.script_path, cycle, stage);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

std::string checkpoint_summary(const std::string& path, bool script) {
  CheckpointNote note;
  const Model model = Model::restore(path, &note);
  const ModelInfo info = model.info();
  const SolverInfo solver = model.solver_info();
  const long lines = std::count(note.script.begin(), note.script.end(), '\n');
  std::string text = fmt::format("{}: EDEM checkpoint, written {} by EDEM {}\n", path, note.saved_at, note.edem_version);
  text += fmt::format("  script: {} ({} lines)\n", note.script_path.empty() ? "(none)" : note.script_path, lines);
  text += fmt::format("  model: \"{}\", {} blocks, {} zones, {} gridpoints, {} joint sets, {} regions\n",
                      model.title(), info.blocks, info.zones, info.gridpoints, info.joint_sets, info.regions);
  text += fmt::format("  cycle {}, stage {}, unbalanced-force ratio {:.3g}\n", solver.cycle, info.stage, solver.ratio);
  // Found now if they were not current; a model not ready to cycle (no zones, a zone without
  // material) has none to show, which is no fault of the file.
  std::string contacts;
  try {
    int slipping = 0;
    for (int c = 0; c < model.contact_count(); ++c) slipping += model.contact(c).state == "slip";
    contacts = fmt::format("{} ({} slipping)", model.contact_count(), slipping);
  } catch (const Error& e) {
    contacts = fmt::format("none yet ({})", e.what());
  }
  text += fmt::format("  contacts: {}\n", contacts);
  text += fmt::format("  potential cracks: {} sections, {} broken ({} shear, {} tension)\n", info.sections,
                      info.cracks, info.shear_cracks, info.tension_cracks);
  text += fmt::format("  bolts: {}\n", model.bolt_count());
  std::string names;
  for (const History& h : model.histories())
    names += fmt::format("{}{} ({} samples{})", names.empty() ? "" : ", ", h.name, h.values.size(),
                         h.quantity.empty() ? ", fn: give it again after restore" : "");
  text += fmt::format("  histories: {}\n", names.empty() ? "none" : names);
  text += fmt::format("  prepass result: {}\n", model.last_prepass() ? "kept" : "none");
  if (script) text += "---- script ----\n" + note.script;
  return text;
}

const Command& save_command() {
  static const Command command{
      .name = "save",
      .help =
          "Saves the whole model (geometry, zones, contacts, cracks, bolts, histories, the last prepass) to an "
          "HDF5 checkpoint that restore() continues from bit for bit. The file also keeps the script's text and "
          "EDEM's version; it is written under a temporary name and renamed, so a run killed while saving "
          "leaves the previous file intact. Lua functions are not saved: after restore() the script registers "
          "its every() callbacks again and gives fn histories and a judge criterion again. From an every() "
          "callback it saves the state at that cycle (periodic checkpoints of one long cycle()). `edem info "
          "FILE` summarises a checkpoint.",
      .form = Form::call,
      .positional =
          {
              {"file", Type::string, "", any_value, kRequired,
               "the checkpoint to write (.h5; under --out when relative)"},
          },
      .run = run_save,
      .usage = "save(\"stage3.h5\")",
  };
  return command;
}

const Command& restore_command() {
  static const Command command{
      .name = "restore",
      .help =
          "Makes a saved checkpoint the current model, in place of the one there is. A missing, truncated, "
          "damaged, foreign or newer file is refused with a message and the current model kept. The restored "
          "model's geometry is fixed; its mechanics, loads, excavations and bolts go on as in any model. "
          "Histories of built-in quantities go on recording; fn histories and a judge criterion must be given "
          "again (same name, same every) before cycling, and every() callbacks registered again.",
      .form = Form::call,
      .positional =
          {
              {"file", Type::string, "", any_value, kRequired,
               "the checkpoint to read (under --out when relative, as save writes it)"},
          },
      .run = run_restore,
      .usage = "restore(\"stage3.h5\")",
  };
  return command;
}

}  // namespace edem
