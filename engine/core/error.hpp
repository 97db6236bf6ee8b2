// Errors the engine reports to its caller.
//
// The engine throws edem::Error for anything a user can cause (bad input, impossible
// geometry, an unstable run). The message says what is wrong in the user's words; the
// interpreter adds the script line and command name. Nothing in the engine catches.
#pragma once

#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace edem {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

template <typename... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
  throw Error(fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace edem
