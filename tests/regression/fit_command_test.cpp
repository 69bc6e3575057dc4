// `plisse fit` as a user runs it (docs/fit.md): Treloar's data fitted with Ogden's three terms,
// the files of -o, the printed material block accepted by a case file, and bad input refused with
// exit status 2 and the place.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "output/json_file.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

const std::string kTreloar =
    std::string(PLISSE_SOURCE_DIR) + "/examples/materials/treloar-1944.csv";

TEST(FitCommand, OgdenToTreloarWritesItsFilesAndABlockACaseAccepts) {
  const auto dir = test::scratch_directory("fit-treloar");
  const test::PlisseResult r =
      test::run_plisse_captured("fit " + kTreloar + " --model ogden -o " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* text : {"ogden (3 terms), 53 points", "uniaxial", "equibiaxial", "planar",
                           "stable (Drucker", "material: {model: ogden, mu1: "})
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
  for (const char* file : {"fit.png", "material.yaml", "fit.json", "fit.csv", "curves.csv"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / file)) << file;
  const nlohmann::json j = read_json_file(dir / "fit.json");
  EXPECT_LT(j.at("rms_relative_error").get<double>(), 0.1);
  EXPECT_TRUE(j.at("broken_rules").empty());
  // The block, as written, is a material a case accepts.
  std::ifstream in(dir / "material.yaml");
  std::string block;
  std::getline(in, block);
  const std::string value = block.substr(block.find('{'));
  const test::PlisseResult check = test::run_plisse_captured(
      "check " + test::example("cube-tension-ogden.yaml") + " --set 'material=" + value + "'");
  EXPECT_EQ(check.status, 0) << check.output;
}

TEST(FitCommand, BadInputIsRefusedWithItsPlace) {
  const auto dir = test::scratch_directory("fit-bad");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.csv") << "mode,stretch,stress\nuniaxial,1.5,0.2\nshear,2,0.3\n";
  std::ofstream(dir / "few.csv") << "mode,stretch,stress\nuniaxial,1.5,0.2\n";
  // Stresses near the largest double: the fitted neo-Hookean's equibiaxial stress at 9 overflows
  // (it printed "100000.00 %" and a block with c1 = 4.7e306).
  std::ofstream(dir / "huge.csv")
      << "mode,stretch,stress\nuniaxial,1.5,1e307\nuniaxial,3,1.7e308\nequibiaxial,9,1.7e308\n";
  const struct {
    std::string args, expected;
  } cases[] = {
      {"fit " + (dir / "bad.csv").string() + " --model neo-hookean",
       "bad.csv:3: key 'mode': unknown test mode 'shear'"},
      {"fit " + (dir / "few.csv").string() + " --model mooney-rivlin",
       "1 points for 2 parameters of 'mooney-rivlin'"},
      {"fit " + kTreloar + " --model rubber", "key 'model': unknown material model 'rubber'"},
      {"fit " + kTreloar + " --model ogden --terms 4", "key 'terms': an Ogden fit has 1 to 3"},
      {"fit " + kTreloar + " --model fibre-reinforced", "'fibre-reinforced' is not isotropic"},
      {"fit " + (dir / "missing.csv").string() + " --model ogden", "missing.csv: cannot read"},
      {"fit " + (dir / "huge.csv").string() + " --model neo-hookean",
       "key 'model': no fit of 'neo-hookean' gives a finite stress at every data point (the best "
       "leaves 1 of 3 points without one"},
  };
  for (const auto& c : cases) {
    const test::PlisseResult r = test::run_plisse_captured(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace plisse
