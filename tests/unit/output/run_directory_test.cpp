#include "io/run_directory.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
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

}  // namespace
}  // namespace plisse
