// The registration table: one line per command. Adding a command: write its spec and runner
// in a cmd_*.cpp file, declare it in commands.hpp, list it here, and regenerate the README
// reference (`edem reference --update README.md`).
#include "commands.hpp"

#include <lua.hpp>

#include "adaptor.hpp"
#include "context.hpp"

namespace edem {

const std::vector<const Command*>& commands() {
  static const std::vector<const Command*> table = {
      &model_command(),          // cmd_model.cpp
      &block_command(),          // cmd_geometry.cpp
      &jset_command(),           //
      &crack_command(),          //
      &crackseed_command(),      // cmd_cracks.cpp
      &region_command(),         //
      &zone_command(),           //
      &material_command(),       // cmd_material.cpp
      &assign_command(),         //
      &joint_material_command(), // cmd_joints.cpp
      &jassign_command(),        //
      &gravity_command(),        // cmd_loads.cpp
      &insitu_command(),         //
      &boundary_command(),       //
      &set_command(),            // cmd_solve.cpp
      &cycle_command(),          //
      &solve_command(),          //
      &reset_command(),          //
      &prepass_command(),        // cmd_prepass.cpp
      &prepass_result_command(), //
      &excavate_command(),       // cmd_excavation.cpp
      &fill_command(),           //
      &stage_command(),          //
      &bolt_material_command(),  // cmd_bolts.cpp
      &bolt_command(),           //
      &bolt_head_command(),      //
      &bolts_command(),          //
      &every_command(),          //
      &cancel_command(),         //
      &history_command(),        // cmd_history.cpp
      &history_write_command(),  //
      &info_command(),           // cmd_query.cpp
      &energy_command(),         //
      &blocks_command(),         //
      &moved_blocks_command(),   //
      &loose_blocks_command(),   //
      &zones_command(),          //
      &gridpoints_command(),     //
      &gp_near_command(),        //
      &zone_at_command(),        //
      &contacts_command(),       //
      &contact_near_command(),   //
      &judge_command(),          // cmd_cracks.cpp
      &cracks_command(),         //
      &sections_command(),       //
      &plot_command(),           // cmd_plot.cpp
      &chart_command(),          // cmd_chart.cpp
      &profile_command(),        // cmd_profile.cpp
      &output_command(),         // cmd_output.cpp
      &save_command(),           // cmd_checkpoint.cpp
      &restore_command(),        //
      &settings_command(),       // cmd_settings.cpp
      &out_dir_command(),        //
      &result_command(),         //
  };
  return table;
}

const Command* find_command(std::string_view name) {
  for (const Command* command : commands())
    if (command->name == name) return command;
  return nullptr;
}

namespace {

// Marks a command as running for as long as it does (Context::running), also when it fails.
class RunningScope {
 public:
  RunningScope(Context& context, Running& running) : context_(context), outer_(context.running) {
    running.outer = outer_;
    context.running = &running;
  }
  ~RunningScope() { context_.running = outer_; }
  RunningScope(const RunningScope&) = delete;
  RunningScope& operator=(const RunningScope&) = delete;

 private:
  Context& context_;
  Running* outer_;
};

// Every command's Lua function: upvalue 1 is its Command, upvalue 2 its table of defaults.
int dispatch(lua_State* L) {
  const auto& command = *static_cast<const Command*>(lua_touserdata(L, lua_upvalueindex(1)));
  Running running{.L = L, .command = command.name, .cycling_at = {}, .outer = nullptr};
  const RunningScope scope(context_of(L), running);
  std::vector<std::string> doubts;
  const int results = guarded(L, command.name, [&] {
    if (Context& context = context_of(L); context.probe != nullptr && command.name != "settings" &&
                                          command.name != "out_dir") {
      context.probe->first_command = command.name;  // edem sweep looks no further
      fail("the script stops here: edem sweep reads its settings{{}} only");
    }
    const Args args = read_args(L, command, lua_upvalueindex(2));
    const int count = command.run(L, context_of(L), args);
    doubts = args.doubts;
    return count;
  });
  for (const std::string& text : doubts) warn(L, command.name, text);
  Context& context = context_of(L);
  if (context.current)
    for (const Model::Notice& n : context.current->take_notices())
      n.warning ? warn(L, command.name, n.text) : note(L, command.name, n.text);
  return results;
}

}  // namespace

void register_commands(lua_State* L) {
  for (const Command* command : commands()) {
    lua_pushlightuserdata(L, const_cast<Command*>(command));
    push_defaults(L, *command);
    lua_pushcclosure(L, dispatch, 2);
    lua_setglobal(L, std::string(command->name).c_str());
  }
}

}  // namespace edem
