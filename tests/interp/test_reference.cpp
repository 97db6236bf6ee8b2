// README.md's language reference must be the one generated from the command schema.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "commands.hpp"
#include "interp_test.hpp"
#include "reference.hpp"

namespace edem {
namespace {

using test::contains;

TEST(Reference, ReadmeIsInSyncWithTheSchema) {
  const std::string readme_path = EDEM_SOURCE_DIR "/README.md";
  std::ifstream in(readme_path);
  ASSERT_TRUE(in) << "cannot read " << readme_path;
  std::stringstream readme;
  readme << in.rdbuf();
  const std::string fix = "regenerate it with: " EDEM_EXE " reference --update " + readme_path;
  const auto section = reference_section(readme.str());
  ASSERT_TRUE(section) << readme_path << " has no " << kReferenceBegin << " ... " << kReferenceEnd
                       << " section; " << fix;
  const std::string expected = fmt::format("\n{}\n", reference_markdown());
  EXPECT_TRUE(*section == expected)
      << "README.md's language reference differs from the command schema; " << fix;
}

TEST(Reference, DocumentsEveryCommandAndKey) {
  const std::string reference = reference_markdown();
  for (const Command* command : commands()) {
    EXPECT_TRUE(contains(reference, "### `" + std::string(command->name) + "`"));
    for (const Key& key : command->keys)
      EXPECT_TRUE(contains(reference, "| `" + std::string(key.name) + "` |"))
          << command->name << "." << key.name;
  }
  EXPECT_TRUE(contains(reference, "| `spacing` | number or list | m | > 0 | required |"));
  EXPECT_TRUE(contains(reference, "| `show` | string or list |  | `regions`, `plastic`, `prepass`, `zones`"));
  EXPECT_TRUE(contains(reference, "| `stress` | numbers or name | Pa | `insitu` |"));
  EXPECT_TRUE(contains(reference, "| items 1, ... (`what`) | string |  | `displacement`, "));
}

TEST(Reference, SplicingReplacesOnlyTheSection) {
  const std::string document =
      "# T\n\n<!-- reference:begin -->\nold\n<!-- reference:end -->\ntail\n";
  EXPECT_EQ(with_reference(document, "new"),
            "# T\n\n<!-- reference:begin -->\nnew\n<!-- reference:end -->\ntail\n");
  EXPECT_EQ(with_reference("# T", "new"),
            "# T\n\n<!-- reference:begin -->\nnew\n<!-- reference:end -->\n");
  EXPECT_EQ(reference_section(with_reference("# T", "new")), "\nnew\n");
  EXPECT_FALSE(reference_section("# no markers"));
}

}  // namespace
}  // namespace edem
