// edem sweep's look at a script before any run: the script runs only up to its settings{} call,
// which records the declared keys here and stops it; any other command reached first stops it
// too, naming itself, so that nothing is built or cycled.
#pragma once

#include <string>
#include <vector>

namespace edem {

// A setting the script declares: its key, its default's Lua type ("number", "string" or
// "boolean") and the default as text.
struct DeclaredSetting {
  std::string key, type, value;
};

struct SettingsProbe {
  bool reached = false;                   // settings{} was called
  std::vector<DeclaredSetting> declared;  // its keys, sorted
  std::string first_command;              // the command that came before any settings{}
};

}  // namespace edem
