// One line of a CSV file, read and written as RFC 4180 has it: commas between fields, a field
// in double quotes may hold commas and doubled quotes. Enough for the tables edem sweep reads
// and writes; a quoted field does not span lines.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace edem {

// The fields of `line` (a final '\r' dropped); a field's surrounding quotes are taken off.
std::vector<std::string> csv_fields(std::string_view line);

// `fields` joined by commas, each quoted where it holds a comma, a quote or a line break.
std::string csv_line(const std::vector<std::string>& fields);

}  // namespace edem
