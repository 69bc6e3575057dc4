// The key tables of docs/case-file.md are exactly what the case-file schema generates, and every
// section has one.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "case/keys.hpp"
#include "core/error.hpp"

namespace plisse {
namespace {

std::string manual() {
  std::ifstream in(std::string(PLISSE_SOURCE_DIR) + "/docs/case-file.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CaseKeys, CommittedManualHasTheGeneratedTables) {
  const std::string doc = manual();
  ASSERT_FALSE(doc.empty()) << "cannot read docs/case-file.md";
  EXPECT_EQ(refresh_case_key_blocks(doc), doc)
      << "the key tables of docs/case-file.md are out of date: regenerate them with "
         "`build/bin/plisse case-keys --update docs/case-file.md`";
}

TEST(CaseKeys, EverySectionHasAGeneratedBlock) {
  const std::string doc = manual();
  for (const std::string& section : case_key_sections())
    EXPECT_NE(doc.find("<!-- generated: " + section + " -->\n"), std::string::npos)
        << "docs/case-file.md has no generated table for '" << section << "'";
}

TEST(CaseKeys, TablesNameKeysVariantsAndRules) {
  const std::string boundary = case_keys_markdown("boundary");
  EXPECT_NE(boundary.find("| applies to |"), std::string::npos) << boundary;
  EXPECT_NE(
      boundary.find("| `value` | list of 3 numbers or `~` | mm | required | | displacement |"),
      std::string::npos)
      << boundary;
  const std::string solver = case_keys_markdown("solver");
  EXPECT_EQ(solver.find("| applies to |"), std::string::npos) << solver;
  EXPECT_NE(solver.find("| `newton.rtol` | number | – | 1e-8 | in (0, 1) |"), std::string::npos)
      << solver;
  EXPECT_NE(solver.find("| `newton.linear.restart` | integer | – | 50 | >= 1; `iterative` only |"),
            std::string::npos)
      << solver;
  EXPECT_NE(solver.find("- `min_step` <= `max_step`\n"), std::string::npos) << solver;
  EXPECT_NE(solver.find("- in `stability`: `branch_switch` needs `check: true`\n"),
            std::string::npos)
      << solver;
  EXPECT_THROW(case_keys_markdown("solvers"), Error);
}

TEST(CaseKeys, RefreshKeepsTheProseAndRefusesBrokenBlocks) {
  const std::string doc = "intro\n<!-- generated: title -->\nold\n<!-- end generated -->\nafter\n";
  EXPECT_EQ(refresh_case_key_blocks(doc), "intro\n<!-- generated: title -->\n" +
                                              case_keys_markdown("title") +
                                              "<!-- end generated -->\nafter\n");
  EXPECT_THROW(refresh_case_key_blocks("<!-- generated: title -->\nno end\n"), Error);
  EXPECT_THROW(refresh_case_key_blocks("<!-- generated: nothing -->\n<!-- end generated -->\n"),
               Error);
}

}  // namespace
}  // namespace plisse
