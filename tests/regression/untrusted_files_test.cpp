// Requirement: every file plisse reads is checked for type and size before it is read, so no
// input can hang it or make it allocate what the file only claims (issue: "Trustworthy, round
// two", item 4). A FIFO named as the case, the mesh, the checkpoint or a run's summary, and
// sparse files that claim 100 GiB, are refused with exit status 2 in seconds; PETSc options that
// name files are refused before PETSc reads them. Every command runs under `timeout` and (but
// under AddressSanitizer) a 4 GiB address-space limit, so a regression fails the test instead of
// hanging the machine.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "support/inflated_octant.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  int status = -1;
  std::string output;
  double seconds = 0.0;
};

/// The limits every command here runs under: 30 s, and 4 GiB of address space except under
/// AddressSanitizer (test::limits).
const std::string kLimits = test::limits(30);

/// `plisse ARGS` under kLimits.
Outcome plisse(const std::string& args) {
  const auto start = std::chrono::steady_clock::now();
  const test::PlisseResult r = test::run_plisse_captured(args, kLimits);
  return {r.status, r.output,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

const std::string kCube = test::example("cube-tension-neo-hookean.yaml");

/// `plisse ARGS` under kLimits after the shell command `before` (e.g. "cd DIR && ").
Outcome plisse_in(const std::string& before, const std::string& args) {
  const test::PlisseResult r = test::run_plisse_captured(args, before + kLimits);
  return {r.status, r.output, 0.0};
}

void expect_refused(const Outcome& r, const std::string& message) {
  EXPECT_EQ(r.status, 2) << r.output;  // 124 would be the timeout: a hang
  EXPECT_LT(r.seconds, 20.0) << r.output;
  EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
}

TEST(UntrustedFiles, AFifoIsRefusedWhereverAFileIsRead) {
  const fs::path dir = test::scratch_directory("untrusted-fifo");
  fs::create_directories(dir);
  const fs::path fifo = dir / "pipe.yaml";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expect_refused(plisse("check " + fifo.string()), "is a FIFO (named pipe), not a case file");
  expect_refused(plisse("run " + fifo.string() + " -o " + (dir / "out").string()),
                 "is a FIFO (named pipe), not a case file");
  EXPECT_FALSE(fs::exists(dir / "out"));

  const fs::path mesh = dir / "pipe.msh";
  ASSERT_EQ(mkfifo(mesh.c_str(), 0600), 0);
  std::ofstream(dir / "case.yaml") << "mesh: {file: pipe.msh}\n"
                                      "material: {model: neo-hookean, c1: 0.2}\n";
  expect_refused(plisse("check " + (dir / "case.yaml").string()), "not a regular file");

  // A finished run whose checkpoint and summary are then replaced by FIFOs.
  const fs::path run = dir / "run";
  ASSERT_EQ(plisse("run " + kCube + " --set solver.steps=2 -o " + run.string()).status, 0);
  fs::remove(run / "checkpoint.bin");
  ASSERT_EQ(mkfifo((run / "checkpoint.bin").c_str(), 0600), 0);
  expect_refused(plisse("run " + kCube + " --set solver.steps=2 --resume " + run.string()),
                 "checkpoint.bin: key '--resume': cannot read: not a regular file");
  fs::remove(run / "summary.json");
  ASSERT_EQ(mkfifo((run / "summary.json").c_str(), 0600), 0);
  expect_refused(plisse("wrinkles " + run.string()),
                 "summary.json: cannot read: not a regular file");
}

TEST(UntrustedFiles, SparseFilesThatClaimHundredsOfGigabytesAreRefusedUnread) {
  const fs::path dir = test::scratch_directory("untrusted-sparse");
  fs::create_directories(dir);
  const auto sparse = [&](const fs::path& file, const std::string& head) {
    std::ofstream(file, std::ios::binary) << head;
    ASSERT_EQ(truncate(file.c_str(), std::int64_t{100} << 30), 0);  // 100 GiB, no blocks
  };
  const fs::path mesh = dir / "huge.msh";
  sparse(mesh, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  std::ofstream(dir / "case.yaml") << "mesh: {file: huge.msh}\n"
                                      "material: {model: neo-hookean, c1: 0.2}\n";
  expect_refused(plisse("check " + (dir / "case.yaml").string()),
                 "reading it needs about 6 bytes of memory per byte");

  const fs::path run = dir / "run";
  ASSERT_EQ(plisse("run " + kCube + " --set solver.steps=2 -o " + run.string()).status, 0);
  // Its magic number but no version after it: refused from its first bytes, unread.
  sparse(run / "checkpoint.bin", "PLISSECK");
  expect_refused(plisse("run " + kCube + " --set solver.steps=2 --resume " + run.string()),
                 "not a usable plisse checkpoint: written by another version");
  sparse(run / "summary.json", "{");
  expect_refused(plisse("wrinkles " + run.string()), "its reader accepts");
  sparse(dir / "big.yaml", "title: x\n");
  expect_refused(plisse("check " + (dir / "big.yaml").string()),
                 "bytes; a case file is at most 16 MiB here");
}

TEST(UntrustedFiles, PetscOptionsThatNameFilesAreRefusedBeforePetscReadsThem) {
  const fs::path dir = test::scratch_directory("untrusted-petsc");
  fs::create_directories(dir);
  // -options_file is acted on as soon as PETSc sees it: a file it could read must not matter.
  std::ofstream(dir / "more.opts") << "-ksp_type gmres\n";
  const Outcome r = plisse("run " + kCube + " -o " + (dir / "out").string() +
                           " --petsc \"-options_file " + (dir / "more.opts").string() + "\"");
  expect_refused(r, "command line: key '--petsc': '-options_file ");
  EXPECT_FALSE(fs::exists(dir / "out"));
  const fs::path timings = dir / "timings.txt";
  expect_refused(plisse("run " + kCube + " -o " + (dir / "out").string() +
                        " --petsc \"-log_view :" + timings.string() + "\""),
                 "'-log_view :" + timings.string() + "' is refused: -log_view is not among");
  EXPECT_FALSE(fs::exists(timings));
  // Text to the log is what PETSc's views are for here.
  const Outcome fine = plisse("run " + kCube + " --set solver.steps=1 -o " + (dir / "ok").string() +
                              " --petsc \"-ksp_view ::ascii_info\"");
  EXPECT_EQ(fine.status, 0) << fine.output;
}

TEST(UntrustedFiles, PetscViewsInBinaryWriteNoFileUnderCheckOrRun) {
  // PETSc's binary viewer writes `binaryoutput` (and .info) into the working directory, and
  // -prefix_push viewer_binary_ -filename F points it at any file F: check and run refuse both
  // the same way, and nothing is created or truncated.
  const fs::path dir = test::scratch_directory("untrusted-petsc-binary");
  fs::create_directories(dir / "work");
  const fs::path victim = dir / "victim.txt";
  std::ofstream(victim) << "kept\n";
  const std::string in_work = "cd " + (dir / "work").string() + " && ";
  const std::string push = "-prefix_push viewer_binary_ -filename " + victim.string() +
                           " -prefix_pop -ksp_view_mat binary";
  for (const auto& [options, refused] :
       {std::pair<std::string, std::string>{"-ksp_view_mat binary", "'-ksp_view_mat binary'"},
        {push, "'-prefix_push viewer_binary_'"}}) {
    const std::string set = " --set 'solver.petsc_options=" + options + "'";
    const Outcome check = plisse_in(in_work, "check " + kCube + set);
    expect_refused(check, refused + " is refused");
    const Outcome run = plisse_in(in_work, "run " + kCube + set + " -o " + (dir / "out").string());
    expect_refused(run, refused + " is refused");
    EXPECT_EQ(check.output, run.output);  // the same verdict, in the same words
  }
  expect_refused(
      plisse_in(in_work, "run " + kCube + " --petsc '" + push + "' -o " + (dir / "out").string()),
      "command line: key '--petsc': '-prefix_push viewer_binary_' is refused");
  EXPECT_TRUE(fs::is_empty(dir / "work"));
  EXPECT_FALSE(fs::exists(dir / "out"));
  std::ifstream in(victim);
  std::string kept;
  std::getline(in, kept);
  EXPECT_EQ(kept, "kept");
  EXPECT_FALSE(fs::exists(dir / "victim.txt.info"));
}

TEST(UntrustedFiles, PetscOptionsFromTheEnvironmentAndPetscrcFilesPassTheSameRules) {
  // PETSc reads PETSC_OPTIONS and the .petscrc of the working directory at start-up, as if they
  // were on the command line: a .petscrc in a directory someone sent you is not read at all, and
  // PETSC_OPTIONS is checked like --petsc. Nothing is written to the working directory.
  const fs::path dir = test::scratch_directory("untrusted-petscrc");
  fs::create_directories(dir / "work");
  std::ofstream(dir / "work" / ".petscrc") << "-ksp_view_mat binary\n";
  const std::string in_work = "cd " + (dir / "work").string() + " && ";
  const Outcome run =
      plisse_in(in_work, "run " + kCube + " --set solver.steps=1 -o " + (dir / "out").string());
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_FALSE(fs::exists(dir / "work" / "binaryoutput"));
  const std::string env = in_work + "export PETSC_OPTIONS='-ksp_view_mat binary'; ";
  for (const std::string& command :
       {"check " + kCube, "run " + kCube + " -o " + (dir / "refused").string()}) {
    const Outcome refused = plisse_in(env, command);
    expect_refused(refused, "environment: key 'PETSC_OPTIONS': '-ksp_view_mat binary' is refused");
  }
  EXPECT_FALSE(fs::exists(dir / "refused"));
  EXPECT_FALSE(fs::exists(dir / "work" / "binaryoutput"));
  // An option the rules allow is taken from the environment as from --petsc.
  const Outcome allowed =
      plisse_in(in_work + "export PETSC_OPTIONS='-ksp_view ::ascii_info'; ",
                "run " + kCube + " --set solver.steps=1 -o " + (dir / "allowed").string());
  EXPECT_EQ(allowed.status, 0) << allowed.output;
}

/// A small shell with a wrinkle ring: its runs write every file plisse wrinkles and plot read.
const std::string kShell =
    test::inflated_octant_case(test::kSmallOctantMesh,
                               "solver: {steps: 2, max_steps: 4}\n"
                               "output: {wrinkles: {axis: y, rings_deg: [45]}}\n");

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

TEST(UntrustedFiles, FilesLargerThanARunOfTheCaseWritesAreRefusedBeforeTheyAreRead) {
  const fs::path dir = test::scratch_directory("untrusted-bounds");
  fs::create_directories(dir);
  const fs::path case_file = dir / "shell.yaml", run = dir / "run";
  std::ofstream(case_file) << kShell;
  ASSERT_EQ(plisse("run " + case_file.string() + " -o " + run.string()).status, 0);
  const std::string resume = "run " + case_file.string() + " --resume " + run.string();
  const auto keep = [&](const std::string& name) { return bytes_of(run / name); };
  const auto put = [&](const std::string& name, const std::string& bytes) {
    fs::remove(run / name);
    std::ofstream(run / name, std::ios::binary) << bytes;
  };
  const auto sparse = [&](const std::string& name, const std::string& head) {
    put(name, head);
    ASSERT_EQ(truncate((run / name).c_str(), std::int64_t{2} << 30), 0);  // 2 GiB, no blocks
  };

  // A 2 GiB checkpoint: its type is read first; a right one is larger than the memory allows.
  const std::string checkpoint = keep("checkpoint.bin");
  sparse("checkpoint.bin", "NOTPLISSE");
  expect_refused(plisse(resume),
                 "checkpoint.bin: key '--resume': not a usable plisse checkpoint: "
                 "wrong file type");
  sparse("checkpoint.bin", checkpoint.substr(0, 12));
  expect_refused(plisse(resume),
                 "checkpoint.bin: key '--resume': cannot read: the file is "
                 "2147483648 bytes, more than the");
  put("checkpoint.bin", checkpoint);

  // A 200 MiB summary.json, parsed, would take gigabytes.
  const std::string summary = keep("summary.json");
  put("summary.json", "{\"a\": \"");
  ASSERT_EQ(truncate((run / "summary.json").c_str(), std::int64_t{200} << 20), 0);
  expect_refused(plisse("wrinkles " + run.string()),
                 "summary.json: cannot read: the file is 209715200 bytes, more than the "
                 "67108864 its reader accepts");
  expect_refused(plisse("plot " + run.string()), "summary.json: 209715200 bytes, more than the");
  put("summary.json", summary);

  // More history rows than the case's max_steps (4) lets a run write.
  const std::string history = keep("history.csv");
  const std::string rows = history.substr(history.find('\n') + 1);
  put("history.csv", history + rows + rows + rows);
  expect_refused(plisse(resume), "history.csv: holds 8 rows; a run of this case writes at most 4");
  put("history.csv", "step,time,load_factor,newton_iterations,residual_norm\n1,0.5,x,1,1\n");
  expect_refused(plisse("plot " + run.string()), "history.csv: not a history plisse writes");
  put("history.csv", history);

  // A step file of 2^28 points whose zlib blocks would inflate to 12 GiB (23 MB on disk).
  const std::string step = keep("step_0002.vtu");
  const std::string bomb = (run / "step_0002.vtu").string();
  fs::remove(bomb);
  ASSERT_EQ(std::system(("/usr/bin/python3 " + std::string(PLISSE_SOURCE_DIR) +
                         "/tests/data/bombs/vtu_zlib_bomb.py " + bomb)
                            .c_str()),
            0);
  expect_refused(plisse("wrinkles " + run.string() + " --step 2"), "step_0002.vtu: key '--step': ");
  expect_refused(plisse("plot " + run.string()),
                 "step_0002.vtu: its header does not fit the run's mesh");
  put("step_0002.vtu", step);
  EXPECT_EQ(plisse("wrinkles " + run.string() + " --step 2").status, 0);
}

TEST(UntrustedFiles, ALongSetKeyPathIsRefusedNotWalked) {
  // 30 000 parts overflowed the stack of the recursive walk that assigns an override.
  std::string key = "a";
  for (int i = 1; i < 30000; ++i) key += ".a";
  expect_refused(plisse("check " + kCube + " --set " + key + "=1"),
                 "the key path has more than 32 parts");
}

}  // namespace
}  // namespace plisse
