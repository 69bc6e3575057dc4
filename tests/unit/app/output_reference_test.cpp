// The output reference: docs/output.md holds exactly the generated tables, names match their
// patterns, and the writers' checks refuse an undocumented column, field or summary key.
#include "app/output_reference.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "output/generated_blocks.hpp"

namespace plisse::app {
namespace {

std::string output_doc() {
  std::ifstream in(std::string(PLISSE_SOURCE_DIR) + "/docs/output.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(OutputReference, CommittedDocHasTheGeneratedTables) {
  const std::string doc = output_doc();
  ASSERT_FALSE(doc.empty()) << "cannot read docs/output.md";
  for (const std::string& section : output_reference_sections())
    EXPECT_NE(doc.find("<!-- generated: " + section + " -->\n"), std::string::npos) << section;
  EXPECT_EQ(refresh_generated_blocks(doc, output_reference_markdown), doc)
      << "the tables of docs/output.md are out of date: regenerate them with "
         "`build/bin/plisse outputs --update docs/output.md`";
}

TEST(OutputReference, EveryEntryHasAUnitAWhenAndAMeaningAndNoNameTwice) {
  for (const OutputTable table : {OutputTable::history, OutputTable::summary,
                                  OutputTable::vtu_point, OutputTable::vtu_cell}) {
    std::set<std::string> names;
    for (const OutputEntry& e : output_reference(table)) {
      EXPECT_FALSE(e.unit.empty()) << e.name;
      EXPECT_FALSE(e.when.empty()) << e.name;
      EXPECT_GT(e.meaning.size(), 5u) << e.name;
      EXPECT_TRUE(names.insert(e.name).second) << e.name << " twice";
    }
  }
}

TEST(OutputReference, NamesFindTheirMostSpecificPattern) {
  const auto unit_of = [](OutputTable table, const std::string& name) {
    const OutputEntry* e = find_output_entry(table, name);
    return e ? e->unit : std::string("(none)");
  };
  EXPECT_EQ(unit_of(OutputTable::history, "step"), "–");
  EXPECT_EQ(unit_of(OutputTable::history, "pressure:gas"), "MPa");
  EXPECT_EQ(unit_of(OutputTable::history, "full_volume:gas"), "mm³");
  EXPECT_EQ(unit_of(OutputTable::history, "force_y:punch"), "N");
  EXPECT_EQ(unit_of(OutputTable::history, "moment_z:end"), "N mm");
  EXPECT_EQ(unit_of(OutputTable::history, "pressure:"), "(none)");  // a name is not empty
  EXPECT_EQ(unit_of(OutputTable::history, "steps"), "(none)");
  // contact_pressure_<die> is more specific than contact_<die>, which matches it too.
  EXPECT_EQ(find_output_entry(OutputTable::vtu_point, "contact_pressure_punch")->name,
            "contact_pressure_<die>");
  EXPECT_EQ(find_output_entry(OutputTable::vtu_point, "contact_punch")->name, "contact_<die>");
  EXPECT_EQ(unit_of(OutputTable::vtu_point, "mode_12"), "–");
  EXPECT_EQ(unit_of(OutputTable::summary, "final.ux:apex"), "as the column");
  EXPECT_EQ(unit_of(OutputTable::summary, "wall_time.total"), "s");
  EXPECT_THROW(require_output_entry(OutputTable::vtu_cell, "strain"), Error);
  EXPECT_NO_THROW(require_output_entry(OutputTable::vtu_cell, "principal_stretches"));
}

TEST(OutputReference, SummaryKeysAreCheckedAtEveryDepth) {
  const nlohmann::json documented = {
      {"steps", 3},
      {"overrides", nlohmann::json::array({"a=1"})},
      {"wall_time", {{"total", 1.0}}},
      {"stability",
       {{"instabilities", nlohmann::json::array({{{"step", 2}, {"eigenvalues", {-1.0}}}})}}},
      {"final", {{"pressure:gas", 0.1}}}};
  EXPECT_NO_THROW(require_documented_summary(documented));
  nlohmann::json nested = documented;
  nested["wall_time"]["coffee"] = 1.0;
  EXPECT_THROW(require_documented_summary(nested), Error);
  nlohmann::json in_array = documented;
  in_array["stability"]["instabilities"][0]["colour"] = "red";
  EXPECT_THROW(require_documented_summary(in_array), Error);
  EXPECT_THROW(require_documented_summary({{"shoe_size", 42}}), Error);
}

}  // namespace
}  // namespace plisse::app
