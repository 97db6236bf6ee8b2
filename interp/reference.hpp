// The language reference in markdown, generated from the command schema.
//
// README.md carries it between two markers; `edem reference --update README.md` rewrites that
// section, and a test fails while README.md and the schema differ.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace edem {

inline constexpr std::string_view kReferenceBegin = "<!-- reference:begin -->";
inline constexpr std::string_view kReferenceEnd = "<!-- reference:end -->";

// The reference: an introduction, the types, then one section per command.
std::string reference_markdown();

// The text between the markers of `document` (markers excluded), or nothing if it has none.
std::optional<std::string> reference_section(std::string_view document);

// `document` with the text between the markers replaced by "\n" + reference + "\n"; the
// markers and the section are appended when the document has none.
std::string with_reference(std::string_view document, std::string_view reference);

}  // namespace edem
