// The message a check throws edem::Error with, for tests of bad input.
#pragma once

#include <string>

#include "core/error.hpp"

namespace edem {

// What `run()` throws as edem::Error; empty when it throws nothing.
template <class Run> std::string error_of(Run&& run) {
  try {
    run();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

}  // namespace edem
