// End to end: the built `plisse check` exits 0 on a valid case and 2 on bad input, with a message
// naming file:line:column and the key (DESIGN.md, interface contract).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace {

struct Result {
  int status = -1;
  std::string output;  // stdout and stderr
};

Result run_plisse(const std::string& args) {
  const std::string command = std::string(PLISSE_BINARY_DIR) + "/bin/plisse " + args + " 2>&1";
  Result r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (const std::size_t n = fread(buffer, 1, sizeof buffer, pipe)) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

const std::string kCases = std::string(PLISSE_SOURCE_DIR) + "/tests/data/cases/";

TEST(CheckCommand, ValidCaseExitsZeroWithASummary) {
  const Result r = run_plisse("check " + kCases + "complete.yaml");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("valid"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("mooney-rivlin"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("27 nodes, 48 tetrahedra"), std::string::npos) << r.output;  // 3^3 nodes
  EXPECT_NE(r.output.find("top (8 triangles)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("3 boundary conditions, 2 loads, 2 cavities, 3 dies, 1 probe\n"),
            std::string::npos)
      << r.output;
}

TEST(CheckCommand, OverridesApply) {
  const Result r =
      run_plisse("check " + kCases + "complete.yaml --set mesh.divisions=3 --set solver.steps=80");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("64 nodes, 162 tetrahedra"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("80 initial steps"), std::string::npos) << r.output;
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
