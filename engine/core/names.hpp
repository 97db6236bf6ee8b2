// Did-you-mean hints for misspelt names (commands, keys, regions).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace edem {

// Levenshtein distance between two ASCII strings, case-insensitive.
int edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` if it is close enough to be a likely typo, else "".
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" or "" when nothing is close.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace edem
