#include "output/run_directory.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/error.hpp"
#include "output/atomic_file.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::entries;
using test::ScratchDir;

TEST(RunDirectory, CreatesParentsAndNamesTheContractFiles) {
  const ScratchDir scratch;
  const RunDirectory run(scratch.path() / "runs" / "balloon" / "");
  EXPECT_TRUE(std::filesystem::is_directory(scratch.path() / "runs" / "balloon"));
  EXPECT_TRUE(entries(run.directory()).empty());  // the probe file is gone
  EXPECT_EQ(run.directory(), scratch.path() / "runs" / "balloon");
  EXPECT_EQ(run.history_csv(), run.directory() / "history.csv");
  EXPECT_EQ(run.summary_json(), run.directory() / "summary.json");
  EXPECT_EQ(run.solution_pvd(), run.directory() / "solution.pvd");
  EXPECT_EQ(run.log_txt(), run.directory() / "log.txt");
  EXPECT_EQ(run.step_vtu(7), run.directory() / "step_0007.vtu");
}

TEST(RunDirectory, StepFileNamesHaveAtLeastFourDigits) {
  EXPECT_EQ(RunDirectory::step_file_name(0), "step_0000.vtu");
  EXPECT_EQ(RunDirectory::step_file_name(42), "step_0042.vtu");
  EXPECT_EQ(RunDirectory::step_file_name(9999), "step_9999.vtu");
  EXPECT_EQ(RunDirectory::step_file_name(12345), "step_12345.vtu");
  EXPECT_THROW(RunDirectory::step_file_name(-1), Error);
}

TEST(RunDirectory, ExistingDirectoryKeepsItsFiles) {
  const ScratchDir scratch;
  write_file_atomically(scratch / "notes.txt", "kept");
  const RunDirectory run(scratch.path());
  EXPECT_EQ(entries(scratch.path()), std::set<std::string>{"notes.txt"});
}

TEST(RunDirectory, PathUnderARegularFileIsAnInputErrorOnOption) {
  const ScratchDir scratch;
  write_file_atomically(scratch / "file", "x");
  const std::filesystem::path wanted = scratch / "file" / "out";
  try {
    RunDirectory run(wanted);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().file, wanted.string());
    EXPECT_EQ(e.place().key, "-o");
    EXPECT_NE(e.rule().find("Not a directory"), std::string::npos) << e.rule();
  }
  // The output path itself being a regular file is refused too.
  EXPECT_THROW(RunDirectory(scratch / "file"), InputError);
}

TEST(RunDirectory, RunFilesAreTheContractsNamesOnly) {
  const ScratchDir scratch;
  for (const char* name :
       {"history.csv", "summary.json", "solution.pvd", "log.txt", "checkpoint.bin",
        "wrinkle_spectrum.csv", "wrinkles.json", "step_0001.vtu", "step_12345.vtu",
        "step_0002.pvtu", "step_0002_p0.vtu", "step_0002_p13.vtu", "notes.txt", "step_1.vtk",
        "step_x.vtu", "step_0002_p.vtu", "step_0003_p1.pvtu", "mesh.msh", "history.csv.bak"})
    write_file_atomically(scratch / name, "x");
  // A directory is the user's whatever its name, also an empty one that remove() would take.
  std::filesystem::create_directory(scratch / "step_0004.vtu");
  std::vector<std::string> names;
  for (const auto& file : run_files(scratch.path())) names.push_back(file.filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{
                       "checkpoint.bin", "history.csv", "log.txt", "solution.pvd", "step_0001.vtu",
                       "step_0002.pvtu", "step_0002_p0.vtu", "step_0002_p13.vtu", "step_12345.vtu",
                       "summary.json", "wrinkle_spectrum.csv", "wrinkles.json"}));
  EXPECT_EQ(remove_run_files(scratch.path()), 12);
  EXPECT_EQ(
      entries(scratch.path()),
      (std::set<std::string>{"notes.txt", "step_1.vtk", "step_x.vtu", "step_0002_p.vtu",
                             "step_0003_p1.pvtu", "mesh.msh", "history.csv.bak", "step_0004.vtu"}));
}

TEST(RunDirectory, OutputPathProblemsAreSeenWithoutWriting) {
  const test::ScratchDir dir;
  // Nothing there yet, or an empty directory: nothing in the way, and nothing created.
  EXPECT_EQ(output_path_problem(dir / "new" / "run"), "");
  EXPECT_FALSE(std::filesystem::exists(dir / "new"));
  EXPECT_EQ(output_path_problem(dir.path()), "");
  // A regular file on the way.
  write_file_atomically(dir / "file", "x");
  EXPECT_NE(output_path_problem(dir / "file" / "run")
                .find("cannot create the output directory: '" + (dir / "file").string() +
                      "' exists and is not a directory"),
            std::string::npos);
  // Directories under the names of a run's files; the user's own directories are no problem.
  std::filesystem::create_directories(dir / "run" / "history.csv");
  std::filesystem::create_directories(dir / "run" / "step_0003.vtu");
  std::filesystem::create_directories(dir / "run" / "figures");
  EXPECT_EQ(output_path_problem(dir / "run"),
            "holds a directory where the run writes a file (history.csv, step_0003.vtu): move it "
            "away or choose another -o");
  std::filesystem::remove(dir / "run" / "history.csv");
  std::filesystem::remove(dir / "run" / "step_0003.vtu");
  EXPECT_EQ(output_path_problem(dir / "run"), "");
}

TEST(DirectoryLock, OneHolderAtATimeNamedInTheRefusalAndTheFileGoesWithIt) {
  const ScratchDir scratch;
  const InputPlace place{scratch.path().string(), 0, 0, "-o"};
  {
    const DirectoryLock lock(scratch.path(), place);
    EXPECT_NE(test::contents(scratch / DirectoryLock::kFileName)
                  .find("pid " + std::to_string(::getpid()) + " on "),
              std::string::npos);
    // flock locks belong to an open file: a second open in this process is a second holder.
    try {
      const DirectoryLock second(scratch.path(), place);
      ADD_FAILURE() << "a second lock was granted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.place().key, "-o");
      EXPECT_NE(e.rule().find("is in use by another plisse process (pid " +
                              std::to_string(::getpid()) + " on "),
                std::string::npos)
          << e.rule();
    }
  }
  EXPECT_TRUE(entries(scratch.path()).empty());
  // A holder killed by SIGKILL: the kernel releases its lock; its file stays for the next one.
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = fork();
  if (child == 0) {
    const DirectoryLock lock(scratch.path(), place);
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) _exit(1);
    ::pause();
    _exit(0);
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  EXPECT_THROW(DirectoryLock(scratch.path(), place), InputError);
  ::kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(std::filesystem::exists(scratch / DirectoryLock::kFileName));
  { const DirectoryLock lock(scratch.path(), place); }
  EXPECT_TRUE(entries(scratch.path()).empty());
  ::close(ready[0]);
  ::close(ready[1]);
}

}  // namespace
}  // namespace plisse
