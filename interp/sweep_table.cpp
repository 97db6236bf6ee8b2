#include "sweep_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "core/names.hpp"
#include "csv.hpp"

namespace edem {
namespace {

// A character a run's folder name may have.
bool folder_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == '+';
}

// A name for a run's folder under the sweep's: plain characters, not too long for a file
// system, and none of the sweep's own files (sweep.csv, sweep.sbatch, slurm/).
bool folder_safe(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.size() <= 200 && name != "slurm" &&
         name.rfind("sweep", 0) != 0 && std::all_of(name.begin(), name.end(), folder_char);
}

// "case-3_depth-158": a row's settings as a folder name.
std::string name_from(const Settings& settings) {
  std::string name;
  for (const auto& [key, value] : settings) {
    if (!name.empty()) name += '_';
    name += key + '-' + value;
  }
  for (char& c : name)
    if (!folder_char(c)) c = '-';
  return name;
}

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> blank_fields(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> fields;
  for (std::string field; in >> field;) fields.push_back(field);
  return fields;
}

// A line's fields, or nothing for a blank line or a comment.
std::optional<std::vector<std::string>> fields_of(std::string line, bool csv) {
  if (!csv) line = line.substr(0, line.find('#'));
  if (trim(line).empty() || trim(line)[0] == '#') return std::nullopt;
  if (!csv) return blank_fields(line);
  std::vector<std::string> fields = csv_fields(line);
  for (std::string& field : fields) field = trim(field);
  return fields;
}

}  // namespace

SweepTable read_sweep_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("{}: cannot read the table", path);
  SweepTable table{.path = path, .columns = {}, .rows = {}};
  const bool csv_by_name = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
  std::optional<bool> csv;
  std::vector<std::string> header;
  int name_column = -1;
  std::vector<std::string> above;  // the previous row's values, for `=`
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (line == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0)
      text.erase(0, 3);  // a spreadsheet's byte-order mark
    if (!csv) {
      if (trim(text).empty() || trim(text)[0] == '#') continue;
      csv = csv_by_name || text.find(',') != std::string::npos;
    }
    const auto fields = fields_of(text, *csv);
    if (!fields) continue;
    if (header.empty()) {
      header = *fields;
      table.header_line = line;
      for (size_t c = 0; c < header.size(); ++c) {
        const std::string& column = header[c];
        if (column == "name" || column == "description") {
          if (name_column >= 0)
            fail("{}:{}: two name columns ('{}' and '{}')", path, line, header[name_column],
                 column);
          name_column = static_cast<int>(c);
          continue;
        }
        if (!column.empty() && column[0] == '!')
          fail(
              "{}:{}: column '{}': environment columns (YADE's !NAME) are not read; give the run's "
              "threads "
              "with edem sweep --threads",
              path, line, column);
        if (column == "status" || column == "seconds" || column == "message")
          fail(
              "{}:{}: column '{}' is one the sweep writes itself (name, status, seconds, message); "
              "a setting "
              "of that name cannot be swept",
              path, line, column);
        if (!is_identifier(column))
          fail(
              "{}:{}: column {}: '{}' is not a setting's name (letters, digits, _; not a digit "
              "first)",
              path, line, c + 1, column);
        if (std::count(header.begin(), header.begin() + static_cast<long>(c), column) > 0)
          fail("{}:{}: column '{}' is named twice", path, line, column);
        table.columns.push_back(column);
      }
      continue;
    }
    if (fields->size() != header.size()) {
      const bool fewer = fields->size() < header.size();
      fail("{}:{}: {} values for {} columns ({})", path, line, fields->size(), header.size(),
           fewer ? fmt::format("no value for column '{}'", header[fields->size()])
                 : fmt::format("'{}' is beyond the last column, '{}'", (*fields)[header.size()],
                               header.back()));
    }
    std::vector<std::string> values = *fields;
    for (size_t c = 0; c < header.size(); ++c) {
      if (!*csv && values[c] == "=") {
        if (above.empty())
          fail("{}:{}: column '{}': '=' repeats the value above, and this is the first row", path,
               line, header[c]);
        values[c] = above[c];
      }
      if (values[c].empty())
        fail("{}:{}: column '{}' has no value (leave the column out for the script's default)",
             path, line, header[c]);
    }
    above = values;
    SweepRow row{.name = {}, .line = line, .settings = {}};
    for (size_t c = 0; c < header.size(); ++c) {
      if (static_cast<int>(c) == name_column)
        row.name = values[c];
      else
        row.settings.emplace_back(header[c], values[c]);
    }
    if (name_column < 0)
      row.name = row.settings.empty() ? fmt::format("row-{}", table.rows.size() + 1)
                                      : name_from(row.settings);
    if (!folder_safe(row.name))
      fail(
          "{}:{}: name '{}' cannot name a run's folder: use letters, digits and _ - . + only, at "
          "most 200 of "
          "them, and not slurm or sweep... (the sweep's own files)",
          path, line, row.name);
    for (const SweepRow& earlier : table.rows)
      if (earlier.name == row.name)
        fail("{}:{}: the name '{}' is row {}'s (line {}) too: {}", path, line, row.name,
             &earlier - table.rows.data() + 1, earlier.line,
             name_column >= 0 ? "each run needs a name of its own"
             : earlier.settings == row.settings
                 ? "the two rows are the same run"
                 : "give the runs names of their own (a name column)");
    table.rows.push_back(std::move(row));
  }
  if (header.empty())
    fail("{}: the table is empty: give a line of column names, then a row per run", path);
  if (table.rows.empty()) fail("{}: the table has column names but no runs", path);
  return table;
}

void check_sweep_table(const SweepTable& table, const std::vector<DeclaredSetting>& declared,
                       const std::string& script, const Settings& common) {
  std::vector<std::string> keys;
  for (const DeclaredSetting& d : declared) keys.push_back(d.key);
  const auto declaration = [&](const std::string& key) {
    return std::find_if(declared.begin(), declared.end(),
                        [&](const DeclaredSetting& d) { return d.key == key; });
  };
  for (const std::string& column : table.columns) {
    if (declaration(column) == declared.end())
      fail("{}:{}: column '{}': {} has no setting '{}'{} (its settings: {})", table.path,
           table.header_line, column, script, column, did_you_mean(column, keys),
           fmt::join(keys, ", "));
    for (const auto& [key, value] : common)
      if (key == column)
        fail("{}: column '{}' is set for every run too (--set {}={}): one or the other", table.path,
             column, key, value);
  }
  for (const auto& [key, value] : common)
    if (declaration(key) == declared.end())
      fail("--set {}={}: {} has no setting '{}'{} (its settings: {})", key, value, script, key,
           did_you_mean(key, keys), fmt::join(keys, ", "));
  // Where a value is read wrongly: "TABLE:LINE: row 'NAME', column 'KEY'", or the --set.
  const auto check_value = [&](const std::string& where, const std::string& key,
                               const std::string& value) {
    const DeclaredSetting& d = *declaration(key);
    if (d.type == "number") {
      char* end = nullptr;
      const double number = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !std::isfinite(number))
        fail("{}: '{}' is not a number ({}'s default is {})", where, value, key, d.value);
    } else if (d.type == "boolean" && value != "true" && value != "false") {
      fail("{}: '{}' is not true or false ({}'s default is {})", where, value, key, d.value);
    }
  };
  for (const auto& [key, value] : common)
    check_value(fmt::format("--set {}={}", key, value), key, value);
  for (const SweepRow& row : table.rows)
    for (const auto& [key, value] : row.settings)
      check_value(fmt::format("{}:{}: row '{}', column '{}'", table.path, row.line, row.name, key),
                  key, value);
}

}  // namespace edem
