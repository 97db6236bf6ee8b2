// Did-you-mean hints for misspelt names (commands, keys, regions).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace edem {

// A name as Lua and the settings take it: letters, digits and _, not a digit first.
bool is_identifier(std::string_view name);

// Levenshtein distance between two ASCII strings, case-insensitive, a swap of two neighbouring
// letters counting as one edit.
int edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` if it is close enough to be a likely typo, else "".
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" or "" when nothing is close.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" when one is close, else " (there are: a, b, c)", the first ten.
std::string did_you_mean_or_list(std::string_view name, const std::vector<std::string>& candidates);

// The position of the item called `name` among `items` (anything with a `name`); throws
// edem::Error "unknown <what> 'name'" with a did-you-mean hint or the names there are, or, when
// there are none, how to define one (`command`, e.g. "material{...}").
template <typename Items>
int index_of_name(const Items& items, std::string_view name, std::string_view what,
                  std::string_view command) {
  std::vector<std::string> names;
  for (const auto& item : items) {
    if (item.name == name) return static_cast<int>(names.size());
    names.push_back(item.name);
  }
  if (names.empty()) fail("unknown {} '{}': no {} has been defined", what, name, command);
  fail("unknown {} '{}'{}", what, name, did_you_mean_or_list(name, names));
}

}  // namespace edem
