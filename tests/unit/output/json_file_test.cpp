#include "output/json_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::contents;
using test::entries;
using test::ScratchDir;

TEST(JsonFile, SummaryRoundTripsExactly) {
  const ScratchDir dir;
  const nlohmann::json summary = {
      {"dofs", 123456},
      {"elements", 7890},
      {"wall_time_s", {{"assembly", 1.0 / 3.0}, {"solve", 0.1}}},
      {"peak_memory_mb", 512.25},
      {"wrinkles",
       nlohmann::json::array({{{"ring_deg", 30}, {"count", 14}, {"amplitude_mm", 1e-3}},
                              {{"ring_deg", 45}, {"count", 12}, {"amplitude_mm", 2.5e-4}}})},
      {"case", "balloon \"quarter\" \u00e9"}};
  write_json_file(dir / "summary.json", summary);
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"summary.json"});
  const std::string text = contents(dir / "summary.json");
  EXPECT_NE(text.find("\n  \"dofs\": 123456"), std::string::npos);  // pretty printed, indent 2
  EXPECT_EQ(text.back(), '\n');
  const nlohmann::json read = read_json_file(dir / "summary.json");
  EXPECT_EQ(read, summary);
  EXPECT_EQ(read["wall_time_s"]["assembly"].get<double>(), 1.0 / 3.0);  // bit-exact
}

TEST(JsonFile, NonFiniteNumbersBecomeNull) {
  const ScratchDir dir;
  const nlohmann::json summary = {{"amplitude", std::nan("")},
                                  {"growth", std::numeric_limits<double>::infinity()},
                                  {"finite", 2.0}};
  write_json_file(dir / "summary.json", summary);
  const nlohmann::json read = read_json_file(dir / "summary.json");  // parses: valid JSON
  EXPECT_TRUE(read["amplitude"].is_null());
  EXPECT_TRUE(read["growth"].is_null());
  EXPECT_EQ(read["finite"].get<double>(), 2.0);
}

TEST(JsonFile, InvalidJsonGivesInputErrorWithLineAndColumn) {
  const ScratchDir dir;
  std::ofstream(dir / "summary.json") << "{\n  \"dofs\": 12,\n  \"elements\": ]\n}\n";
  try {
    read_json_file(dir / "summary.json");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().file, (dir / "summary.json").string());
    EXPECT_EQ(e.place().line, 3);
    EXPECT_EQ(e.place().column, 15);  // the ']'
  }
  EXPECT_THROW(read_json_file(dir / "missing.json"), InputError);
}

TEST(JsonFile, InvalidUtf8IsAnErrorAndWritesNothing) {
  const ScratchDir dir;
  EXPECT_THROW(write_json_file(dir / "summary.json", {{"name", std::string("\xff\xfe")}}), Error);
  EXPECT_TRUE(entries(dir.path()).empty());
}

}  // namespace
}  // namespace plisse
