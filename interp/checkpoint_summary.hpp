// `edem info FILE`: what a checkpoint holds, in a few lines (interp/cmd_checkpoint.cpp).
#pragma once

#include <string>

namespace edem {

// Restores `path` (checking all of it) and describes it; with `script`, the saved script's text
// follows. Throws edem::Error when the file cannot be restored.
std::string checkpoint_summary(const std::string& path, bool script);

}  // namespace edem
