// End to end: the built `plisse check` exits 0 on a valid case and 2 on bad input, with a message
// naming file:line:column and the key (docs/architecture.md, "Interface contract").
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "support/run_plisse.hpp"

namespace {

using Result = plisse::test::PlisseResult;

Result run_plisse(const std::string& args) { return plisse::test::run_plisse_captured(args); }

const std::string kCases = std::string(PLISSE_SOURCE_DIR) + "/tests/data/cases/";

// A first word that names no command is refused with exit status 2, also with --help (CLI11 alone
// printed the general help and exited 0); `case-keys --update` on a file that has no generated
// block is refused instead of reported "up to date".
TEST(CommandLine, UnknownCommandAndAManualWithoutBlocksExitTwo) {
  Result r = run_plisse("NOSUCH --help");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("unknown command 'NOSUCH' (commands: run, check"), std::string::npos)
      << r.output;
  r = run_plisse("NOSUCH");
  EXPECT_EQ(r.status, 2) << r.output;
  // An option of another command names the command it belongs to.
  r = run_plisse("check -n 1000 '" + std::string(PLISSE_SOURCE_DIR) +
                 "/examples/cube-tension-neo-hookean.yaml'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("check takes no -n: it is an option of plisse run"), std::string::npos)
      << r.output;
  r = run_plisse("--version");
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string readme = std::string(PLISSE_SOURCE_DIR) + "/README.md";
  for (const char* command : {"case-keys", "outputs"}) {
    r = run_plisse(std::string(command) + " --update " + readme);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("has no generated block"), std::string::npos) << r.output;
  }
}

TEST(CheckCommand, ValidCaseExitsZeroWithASummary) {
  const std::string balloon = std::string(PLISSE_SOURCE_DIR) + "/examples/balloon-limit-point.yaml";
  const Result r = run_plisse("check " + balloon);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("valid"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("neo-hookean: c1 = 0.1 MPa"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("678 nodes, 2412 tetrahedra"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("inner (402 triangles)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(
                "3 boundary conditions, 0 loads, 1 cavity, 0 dies, 0 caps, 0 contacts, 1 probe\n"),
            std::string::npos)
      << r.output;
}

// The wrinkle measures the run will take: rings, lines (length, points, a mirrored end), the
// surface whose tension field is counted and the threshold in mm (0.1 t).
TEST(CheckCommand, TheSummaryNamesTheWrinkleMeasures) {
  const std::string sheet = std::string(PLISSE_SOURCE_DIR) + "/examples/sheet-wrinkles-line.yaml";
  const Result r = run_plisse("check " + sheet + " --set output.wrinkles.rings_deg=[10,20]");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("  wrinkles  2 rings about y, line across (10 mm, 200 points, mirrored "
                          "at its start), tension field of 'top'; wrinkled above 0.002 mm\n"),
            std::string::npos)
      << r.output;
}

// A region of its own material is named with it, not as a rigid one; the pressure line says how
// many unknowns the regions' own pressures add (82: two per corner node of the coating's
// interface, 41 x 2 of a 40 x 1-cell sheet), or that one field is shared.
TEST(CheckCommand, TheSummaryNamesTheRegionsAndTheirPressures) {
  const std::string strip = std::string(PLISSE_SOURCE_DIR) + "/examples/coated-strip-bending.yaml";
  Result r = run_plisse("check " + strip);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("  region    regions[0] (240 tetrahedra): neo-hookean: c1 = 50 MPa; "
                          "exactly incompressible\n"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("  pressure  a region's own where regions meet: 82 pressure unknowns "
                          "more at the corner nodes they share\n"),
            std::string::npos)
      << r.output;
  r = run_plisse("check " + strip + " --set region_pressure=continuous");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("  pressure  one continuous field across the regions"), std::string::npos)
      << r.output;
}

TEST(CheckCommand, OverridesApply) {
  const std::string balloon = std::string(PLISSE_SOURCE_DIR) + "/examples/balloon-limit-point.yaml";
  const Result r = run_plisse("check " + balloon + " --set mesh.layers=3 --set solver.steps=80");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("904 nodes, 3618 tetrahedra"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("80 initial steps"), std::string::npos) << r.output;
}

TEST(CheckCommand, EverySectionParsesButAnOpenCavityWallIsRefused) {
  // complete.yaml uses every key; its cavities sit on open faces of a cube, which the parser
  // accepts and the physics check (the same as `plisse run`) refuses at the cavity's surface key.
  // (Without the overrides the first refusal is the imperfection: a cube has no wall thickness;
  // then the incremental scheme, which `plisse run` cannot solve and `plisse check` refuses too.)
  Result r = run_plisse("check " + kCases + "complete.yaml");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("complete.yaml:54:3: key 'solver.stability'"), std::string::npos)
      << r.output;
  r = run_plisse("check " + kCases +
                 "complete.yaml --set solver.stability.imperfection=0 "
                 "--set solver.stability.branch_switch=false --set 'output.wrinkles.rings_deg=[]'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("key 'solver.scheme': only the total-lagrangian scheme"),
            std::string::npos)
      << r.output;
  r = run_plisse("check " + kCases +
                 "complete.yaml --set solver.stability.imperfection=0 "
                 "--set solver.stability.branch_switch=false --set 'output.wrinkles.rings_deg=[]' "
                 "--set solver.scheme=total-lagrangian");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("complete.yaml:26:30: key 'cavities[0].surface'"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("is not closed"), std::string::npos) << r.output;
}

TEST(CheckCommand, UnknownTagExitsTwoNamingFileLineColumnAndKey) {
  const Result r = run_plisse("check " + kCases + "bad-tag.yaml");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(kCases +
                          "bad-tag.yaml:7:35: key 'boundary[1].surface': no surface tag 'inner'"),
            std::string::npos)
      << r.output;
}

TEST(CheckCommand, BadValueExitsTwo) {
  const Result r = run_plisse("check " + kCases + "bad-value.yaml");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("bad-value.yaml:5:7: key 'material.c1': must be > 0 (got -0.1)"),
            std::string::npos)
      << r.output;
}

TEST(CheckCommand, BadOverrideExitsTwoNamingSet) {
  const Result r = run_plisse("check " + kCases + "complete.yaml --set solver.steps=0");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--set: key 'solver.steps': must be >= 1 (got 0)"), std::string::npos)
      << r.output;
}

TEST(CheckCommand, MissingCaseFileExitsTwo) {
  const Result r = run_plisse("check " + kCases + "no-such-case.yaml");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("no-such-case.yaml: the case file does not exist"), std::string::npos)
      << r.output;
}

}  // namespace
