// Writing the language reference from the schema, and splicing it into a README.
#include "reference.hpp"

#include <fmt/format.h>

#include "commands.hpp"

namespace edem {
namespace {

std::string_view intro() {
  return R"(## Language reference

*Generated from the command schema (`interp/cmd_*.cpp`) by `edem reference`; do not edit by hand.
After changing a command run `edem reference --update README.md`: a test fails while this section
and the schema differ.*

A script is Lua 5.4 with the commands below as global functions. Most take one table,
`block{ x = {0, 10}, y = {0, 5} }`; queries take plain arguments, `info()`. A command checks all
of its arguments before it changes the model: an unknown key, a wrong type or a value out of
range stops the script with `script.lua:LINE: command: what is wrong`, and nothing is applied.
Units are SI (m, kg, s, Pa); angles are in degrees, counter-clockwise from +x; compression is
negative. `require "edem.name"` loads `stdlib/edem/name.lua`.
)";
}

std::string types_table() {
  std::string out = "| type | written as |\n|---|---|\n";
  for (const Type type : kAllTypes)
    out += fmt::format("| {} | {} |\n", type_name(type), type_written(type));
  return out;
}

std::string default_of(const Key& key) {
  if (key.required()) return "required";
  if (key.has_default()) return fmt::format("`{}`", key.fallback);
  if (!key.absent.empty()) return fmt::format("*{}*", key.absent);
  return {};
}

std::string allowed_of(const Key& key) {
  if (key.choices != nullptr) {
    std::vector<std::string> quoted;
    for (const auto& choice : key.choices()) quoted.push_back(fmt::format("`{}`", choice));
    return fmt::format("{}", fmt::join(quoted, ", "));
  }
  return key.range.text();
}

std::string row(std::string_view what, const Key& key) {
  // Items that take the rest of a table are each one string (a polygon's are its corners).
  const std::string_view type =
      key.rest && key.type == Type::strings ? type_name(Type::string) : type_name(key.type);
  return fmt::format("| {} | {} | {} | {} | {} | {} |\n", what, type, key.unit, allowed_of(key),
                     default_of(key), key.help);
}

// "`call`" or "`one` or `other`": the command's example calls, one a line in its usage.
std::string usages_of(const Command& command) {
  if (command.usage.empty()) return fmt::format("`{}`", usage_of(command));
  std::vector<std::string> calls;
  std::string_view rest = command.usage;
  while (true) {
    const size_t end = rest.find('\n');
    calls.push_back(fmt::format("`{}`", rest.substr(0, end)));
    if (end == std::string_view::npos) break;
    rest.remove_prefix(end + 1);
  }
  return fmt::format("{}", fmt::join(calls, " or "));
}

std::string section(const Command& command) {
  std::string out =
      fmt::format("### `{}`\n\n{}\n\n{}\n", command.name, command.help, usages_of(command));
  if (!command.positional.empty() || !command.keys.empty()) {
    out += "\n| key | type | unit | allowed | default | meaning |\n|---|---|---|---|---|---|\n";
    const bool table = command.form == Form::table;
    for (size_t i = 0; i < command.positional.size(); ++i) {
      const Key& key = command.positional[i];
      const std::string what =
          key.rest ? fmt::format("items {}, ... (`{}`)", i + 1, key.name)
                   : fmt::format("{} {} (`{}`)", table ? "item" : "argument", i + 1, key.name);
      out += row(what, key);
    }
    for (const Key& key : command.keys) out += row(fmt::format("`{}`", key.name), key);
  }
  if (!command.returns.empty()) out += fmt::format("\nReturns {}.\n", command.returns);
  return out;
}

}  // namespace

std::string reference_markdown() {
  std::string out = fmt::format("{}\n{}\n", intro(), types_table());
  std::vector<std::string> links;
  for (const Command* command : commands())
    links.push_back(fmt::format("[`{0}`](#{0})", command->name));
  out += fmt::format("Commands: {}.\n", fmt::join(links, " · "));
  for (const Command* command : commands()) out += fmt::format("\n{}", section(*command));
  return out;
}

std::optional<std::string> reference_section(std::string_view document) {
  const size_t begin = document.find(kReferenceBegin);
  if (begin == std::string_view::npos) return std::nullopt;
  const size_t start = begin + kReferenceBegin.size();
  const size_t end = document.find(kReferenceEnd, start);
  if (end == std::string_view::npos) return std::nullopt;
  return std::string(document.substr(start, end - start));
}

std::string with_reference(std::string_view document, std::string_view reference) {
  const std::string body = fmt::format("\n{}\n", reference);
  const size_t begin = document.find(kReferenceBegin);
  const size_t end = begin == std::string_view::npos ? begin : document.find(kReferenceEnd, begin);
  if (begin == std::string_view::npos || end == std::string_view::npos) {
    std::string_view text = document;
    while (text.ends_with('\n')) text.remove_suffix(1);  // one blank line before the section
    return fmt::format("{}{}{}{}{}\n", text, text.empty() ? "" : "\n\n", kReferenceBegin, body,
                       kReferenceEnd);
  }
  const size_t start = begin + kReferenceBegin.size();
  return fmt::format("{}{}{}", document.substr(0, start), body, document.substr(end));
}

}  // namespace edem
