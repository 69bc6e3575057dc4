// A second load step (`plisse run CASE --from DIR`): a run that starts from the last state of a
// finished one under another case's loads.
// - Hyperelasticity has no memory: a cube pulled to twice its height and then, in a second run
//   from there, let back to 1.4 times, ends in the state of a cube pulled to 1.4 directly, to the
//   solver's tolerance; the second run's own steps start from the first run's state.
// - A second step on another mesh or element, from a directory without a run, together with
//   --resume, or into the first run's own directory is refused (exit status 2) with a message
//   that names --from.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>

#include "output/history_writer.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;
using test::run_plisse_captured;
using test::scratch_directory;

/// A unit cube on three symmetry planes, its top moved by `top` mm along z, by `ramp`.
std::string cube_case(const std::string& top, const std::string& ramp, int steps) {
  return "mesh: {generate: cube, edge: 1.0, divisions: 2}\n"
         "element: mini\n"
         "material: {model: neo-hookean, c1: 0.2}\n"
         "boundary:\n"
         "  - {type: symmetry, surface: sym_x}\n"
         "  - {type: symmetry, surface: sym_y}\n"
         "  - {type: symmetry, surface: sym_z}\n"
         "  - {type: displacement, name: top, surface: top, value: [~, ~, " +
         top + "], ramp: " + ramp +
         "}\n"
         "output: {stretch_axis: z}\n"
         "solver:\n  steps: " +
         std::to_string(steps) + "\n  max_step: " + std::to_string(1.0 / steps) +
         "\n  newton: {rtol: 1.0e-11, atol: 1.0e-12}\n";
}

fs::path write_case(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

double last(const HistoryTable& h, const std::string& column) {
  for (std::size_t k = 0; k < h.columns.size(); ++k)
    if (h.columns[k] == column) return h.rows.back()[k];
  ADD_FAILURE() << "no column " << column;
  return NAN;
}

TEST(SecondStep, UnloadingAPulledCubeEndsWhereADirectPullDoes) {
  const fs::path dir = scratch_directory("second-step");
  const fs::path pull = write_case(dir, "pull.yaml", cube_case("1.0", "[0, 1]", 4));
  // The second step holds the top at 1 mm at its time 0 and lets it back to 0.4 mm.
  const fs::path back = write_case(dir, "back.yaml", cube_case("1.0", "[[0, 1], [1, 0.4]]", 3));
  const fs::path direct = write_case(dir, "direct.yaml", cube_case("0.4", "[0, 1]", 4));
  for (const auto& [file, out, from] : {std::tuple{pull, dir / "pull", std::string()},
                                        {back, dir / "back", " --from " + (dir / "pull").string()},
                                        {direct, dir / "direct", std::string()}}) {
    const auto r = run_plisse_captured("run " + file.string() + " -o " + out.string() + from);
    ASSERT_EQ(r.status, 0) << r.output;
  }
  const HistoryTable first = read_history(dir / "pull" / "history.csv");
  const HistoryTable second = read_history(dir / "back" / "history.csv");
  const HistoryTable straight = read_history(dir / "direct" / "history.csv");
  EXPECT_NEAR(last(first, "stretch"), 2.0, 1e-12);
  ASSERT_GE(second.rows.size(), 3u);
  // Its first step is a third of the way back, on its own clock (max_step 0.333333): the top at
  // 1 - 0.6 t mm, the homogeneous stretch 2 - 0.6 t.
  const double t = second.rows.front()[1];
  EXPECT_NEAR(t, 1.0 / 3.0, 1e-6) << "the second step's own clock";
  const auto stretch = std::find(second.columns.begin(), second.columns.end(), "stretch");
  ASSERT_NE(stretch, second.columns.end());
  EXPECT_NEAR(second.rows.front()[std::size_t(stretch - second.columns.begin())], 2.0 - 0.6 * t,
              1e-9);
  for (const char* column : {"stretch", "stretch_x", "cauchy_zz", "force_z:top", "strain_energy"})
    EXPECT_NEAR(last(second, column), last(straight, column),
                1e-9 * std::max(1.0, std::abs(last(straight, column))))
        << column;
  // The log says where it started.
  std::ifstream log(dir / "back" / "log.txt");
  const std::string text((std::istreambuf_iterator<char>(log)), {});
  EXPECT_NE(text.find("starting from the last state of"), std::string::npos);
}

// A viscoelastic cube (one Maxwell element, β = 1, τ = 0.5 s) pulled to stretch 2 in its first
// step (0.05 s) and held to t = 0.5 s; a second run from it holds for 1 s more. The overstress
// carries over: the second run's stress continues the first one's relaxation, P∞ (1 + β exp(-(t1
// + t2 - 0.025)/τ)) with t1 = 0.5 and t2 the second run's own time, to the solver's tolerance.
// A second step that adds viscoelasticity to an elastic run has no history to start from: refused.
TEST(SecondStep, ViscoelasticRelaxationContinuesInTheSecondRun) {
  const fs::path dir = scratch_directory("second-step-viscoelastic");
  const std::string material =
      "material: {model: neo-hookean, c1: 0.2, viscoelastic: {beta1: 1.0, tau1: 0.5}}\n";
  const auto with_material = [&](std::string text) {
    return text.replace(text.find("material:"),
                        text.find('\n', text.find("material:")) - text.find("material:") + 1,
                        material);
  };
  const fs::path pull = write_case(
      dir, "pull.yaml",
      with_material(cube_case("1.0", "[[0, 0], [0.05, 1], [1, 1]]", 10)) + "  end_time: 0.5\n");
  const fs::path hold =
      write_case(dir, "hold.yaml", with_material(cube_case("1.0", "[[0, 1], [1, 1]]", 10)));
  ASSERT_EQ(run_plisse_captured("run " + pull.string() + " -o " + (dir / "pull").string()).status,
            0);
  const auto held = run_plisse_captured("run " + hold.string() + " -o " + (dir / "hold").string() +
                                        " --from " + (dir / "pull").string());
  ASSERT_EQ(held.status, 0) << held.output;
  const double equilibrium = 2 * 0.2 * (2.0 - 0.25);  // 2 c1 (λ - 1/λ²) at λ = 2
  const HistoryTable first = read_history(dir / "pull" / "history.csv");
  const HistoryTable second = read_history(dir / "hold" / "history.csv");
  ASSERT_GE(second.rows.size(), 3u);
  const auto index = [](const HistoryTable& h, const std::string& name) {
    return std::size_t(std::find(h.columns.begin(), h.columns.end(), name) - h.columns.begin());
  };
  EXPECT_NEAR(first.rows.front()[index(first, "time")], 0.05, 1e-12);
  for (const auto& [h, t0] : {std::pair{&first, 0.0}, {&second, 0.5}})
    for (const auto& row : h->rows) {
      const double t = t0 + row[index(*h, "time")];
      const double expected = equilibrium * (1 + std::exp(-(t - 0.025) / 0.5));
      // The unit cube's top: nominal stress = force.
      EXPECT_NEAR(row[index(*h, "force_z:top")], expected, 1e-8 * equilibrium) << "t " << t;
    }
  // From an elastic run: refused before any step, naming --from.
  const fs::path elastic = write_case(dir, "elastic.yaml", cube_case("1.0", "[0, 1]", 2));
  ASSERT_EQ(
      run_plisse_captured("run " + elastic.string() + " -o " + (dir / "elastic").string()).status,
      0);
  const auto refused =
      run_plisse_captured("run " + hold.string() + " -o " + (dir / "refused").string() +
                          " --from " + (dir / "elastic").string());
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("viscoelasticity and Mullins softening"), std::string::npos)
      << refused.output;
}

TEST(SecondStep, FromAnUnfinishedRunIsRefusedUnlessAskedAndThenSaidInTheLog) {
  const fs::path dir = scratch_directory("second-step-unfinished");
  const fs::path pull = write_case(dir, "pull.yaml", cube_case("0.5", "[0, 1]", 2));
  const auto first = run_plisse_captured("run " + pull.string() + " -o " + (dir / "pull").string());
  ASSERT_EQ(first.status, 0) << first.output;
  // A run killed before its end leaves its checkpoint but no summary.json.
  fs::remove(dir / "pull" / "summary.json");
  const std::string from = " --from " + (dir / "pull").string();
  auto r = run_plisse_captured("run " + pull.string() + " -o " + (dir / "a").string() + from);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("has no summary.json (it was killed, or is still running): a second "
                          "step starts from a completed run; give --from-unfinished"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "a"));
  r = run_plisse_captured("run " + pull.string() + " -o " + (dir / "b").string() + from +
                          " --from-unfinished");
  EXPECT_EQ(r.status, 0) << r.output;
  std::ifstream in(dir / "b" / "log.txt");
  const std::string log((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(
      log.find("--from-unfinished: the run in " + (dir / "pull").string() + " has no summary.json"),
      std::string::npos)
      << log;
}

TEST(SecondStep, AnotherMeshElementOrDirectoryIsRefusedNamingFrom) {
  const fs::path dir = scratch_directory("second-step-refused");
  const fs::path pull = write_case(dir, "pull.yaml", cube_case("0.5", "[0, 1]", 2));
  const auto first = run_plisse_captured("run " + pull.string() + " -o " + (dir / "pull").string());
  ASSERT_EQ(first.status, 0) << first.output;
  const std::string from = " --from " + (dir / "pull").string();
  const struct {
    std::string args, message;
  } refused[] = {
      {"-o " + (dir / "a").string() + from + " --set mesh.divisions=3", "solved another mesh"},
      {"-o " + (dir / "b").string() + from + " --set element=taylor-hood",
       "a second step keeps the element family"},
      {"-o " + (dir / "c").string() + " --from " + (dir / "nowhere").string(), "--from"},
      {"-o " + (dir / "pull").string() + from, "-o must differ from --from"},
      {"--resume " + (dir / "pull").string() + from, "give one of them"},
  };
  for (const auto& r : refused) {
    const auto result = run_plisse_captured("run " + pull.string() + " " + r.args);
    EXPECT_EQ(result.status, 2) << r.args << "\n" << result.output;
    EXPECT_NE(result.output.find(r.message), std::string::npos) << r.args << "\n" << result.output;
    EXPECT_EQ(result.output.find("terminate"), std::string::npos) << result.output;
  }
  EXPECT_FALSE(fs::exists(dir / "a"));
  EXPECT_FALSE(fs::exists(dir / "b"));
}

}  // namespace
}  // namespace plisse
