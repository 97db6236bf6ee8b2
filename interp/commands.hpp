// The index of the language: every command, in the order the reference lists them.
//
// Each command family (cmd_*.cpp) defines its Command specs; commands() lists them all in
// one table, and register_commands() makes each a Lua global that reads its arguments
// against the schema before running.
#pragma once

#include <string>
#include <vector>

#include "schema.hpp"

struct lua_State;

namespace edem {

// The specs, defined one per command in the cmd_*.cpp files.
const Command& model_command();
const Command& block_command();
const Command& jset_command();
const Command& crack_command();
const Command& crackseed_command();
const Command& region_command();
const Command& zone_command();
const Command& material_command();
const Command& assign_command();
const Command& joint_material_command();
const Command& jassign_command();
const Command& gravity_command();
const Command& insitu_command();
const Command& boundary_command();
const Command& set_command();
const Command& cycle_command();
const Command& solve_command();
const Command& prepass_command();
const Command& reset_command();
const Command& every_command();
const Command& cancel_command();
const Command& history_command();
const Command& history_write_command();
const Command& info_command();
const Command& energy_command();
const Command& blocks_command();
const Command& moved_blocks_command();
const Command& loose_blocks_command();
const Command& zones_command();
const Command& gridpoints_command();
const Command& gp_near_command();
const Command& zone_at_command();
const Command& contacts_command();
const Command& judge_command();
const Command& cracks_command();
const Command& sections_command();
const Command& contact_near_command();
const Command& plot_command();
const Command& chart_command();
const Command& profile_command();
const Command& output_command();
const Command& save_command();
const Command& restore_command();
const Command& prepass_result_command();
const Command& excavate_command();
const Command& fill_command();
const Command& stage_command();
const Command& settings_command();
const Command& out_dir_command();
const Command& result_command();
const Command& bolt_material_command();
const Command& bolt_command();
const Command& bolt_head_command();
const Command& bolts_command();

// Every command of the language, in reference order.
const std::vector<const Command*>& commands();

// The command called `name`, or nullptr.
const Command* find_command(std::string_view name);

// Sets a global function for each command in `L` (defaults are evaluated once here).
void register_commands(lua_State* L);

}  // namespace edem
