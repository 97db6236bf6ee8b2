// The table of an `edem sweep`: one run a row, each column a setting of the script (--set KEY),
// an optional `name` column naming the runs. Read as CSV (a .csv file, or a header with commas)
// or as YADE's batch table (columns separated by blanks, `#` comments, `=` repeating the value
// above, `description` as the name column).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "settings_probe.hpp"

namespace edem {

using Settings = std::vector<std::pair<std::string, std::string>>;  // KEY, VALUE as written

struct SweepRow {
  std::string name;  // its own folder's name under the sweep's --out
  int line = 0;      // in the table file
  Settings settings;
};

struct SweepTable {
  std::string path;
  int header_line = 0;
  std::vector<std::string> columns;  // the settings' columns in the table's order (no name column)
  std::vector<SweepRow> rows;
};

// The table at `path`; an Error naming the line for a malformed one (no rows, a row with more or
// fewer values than columns, an empty value, a column named twice, a name used twice).
SweepTable read_sweep_table(const std::string& path);

// An Error naming the row and column for a column `script` does not declare, a value its
// default's type does not read, or a column `common` (--set for every run) gives too.
void check_sweep_table(const SweepTable& table, const std::vector<DeclaredSetting>& declared,
                       const std::string& script, const Settings& common);

}  // namespace edem
