#include "output/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "output/append_file.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::contents;
using test::entries;
using test::ScratchDir;

TEST(AtomicFile, WritesContentExactlyAndLeavesNoTemporaryFile) {
  const ScratchDir dir;
  const std::string content = std::string("line 1\nline 2\n") + '\0' + "binary\xff";
  write_file_atomically(dir / "a.txt", content);
  EXPECT_EQ(contents(dir / "a.txt"), content);
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"a.txt"});
}

TEST(AtomicFile, ReplacesALongerExistingFileWhole) {
  const ScratchDir dir;
  write_file_atomically(dir / "a.txt", std::string(100000, 'x'));
  write_file_atomically(dir / "a.txt", "short");
  EXPECT_EQ(contents(dir / "a.txt"), "short");  // no tail of the old content
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"a.txt"});
}

TEST(AtomicFile, TargetKeepsOldContentUntilCommit) {
  const ScratchDir dir;
  write_file_atomically(dir / "a.vtu", "old");
  std::string expected;
  AtomicFile file(dir / "a.vtu");
  for (int i = 0; i < 1000; ++i) {  // small pieces through the buffer, then one large piece
    const std::string piece = "piece " + std::to_string(i) + "\n";
    file.write(piece);
    expected += piece;
  }
  const std::string large(300000, 'y');
  file.write(large.data(), large.size());
  expected += large;
  EXPECT_EQ(contents(dir / "a.vtu"), "old");  // a reader during the write sees the old file
  EXPECT_EQ(entries(dir.path()).size(), 2u);  // target and the temporary beside it
  EXPECT_EQ(file.temporary().parent_path(), dir.path());
  file.commit();
  EXPECT_EQ(contents(dir / "a.vtu"), expected);
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"a.vtu"});
  EXPECT_THROW(file.write("more"), Error);
}

TEST(AtomicFile, AbandonedWriteRemovesTemporaryAndKeepsOldFile) {
  const ScratchDir dir;
  write_file_atomically(dir / "a.csv", "old,content\n");
  {
    AtomicFile file(dir / "a.csv");
    file.write("new,par");
  }  // destroyed without commit, as when an exception unwinds
  EXPECT_EQ(contents(dir / "a.csv"), "old,content\n");
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"a.csv"});
}

TEST(AtomicFile, MovedFileCommitsOnce) {
  const ScratchDir dir;
  AtomicFile first(dir / "a.txt");
  first.write("abc");
  AtomicFile second(std::move(first));
  second.commit();
  EXPECT_EQ(contents(dir / "a.txt"), "abc");
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"a.txt"});
}

TEST(AtomicFile, UnwritableLocationThrowsErrorWithPathAndReason) {
  const ScratchDir dir;
  const std::filesystem::path target = dir / "missing" / "a.txt";
  try {
    write_file_atomically(target, "x");
    FAIL() << "no exception";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(target.string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(AtomicFile, ReadFileReturnsContentAndReportsMissingFileAsInputError) {
  const ScratchDir dir;
  write_file_atomically(dir / "a.txt", "content\n");
  EXPECT_EQ(read_file(dir / "a.txt"), "content\n");
  try {
    read_file(dir / "b.txt");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().file, (dir / "b.txt").string());
    EXPECT_NE(e.rule().find("No such file or directory"), std::string::npos) << e.rule();
  }
}

TEST(AtomicFile, StaleTemporariesOfDeadWritersAreRemovedLiveOnesKept) {
  // A real dead process: a child that has exited and been reaped (its pid is free, so kill(pid, 0)
  // reports ESRCH unless the system reused it within these few lines).
  const pid_t child = fork();
  if (child == 0) _exit(0);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  const ScratchDir dir;
  const std::string dead = ".step_0006.vtu.tmp." + std::to_string(child) + ".28";
  const std::string live = ".history.csv.tmp." + std::to_string(::getpid()) + ".3";
  for (const std::string& name : {dead, live, std::string(".x.tmp.12a.1"),
                                  std::string("step_0006.vtu"), std::string("a.tmp.1.2")})
    write_file_atomically(dir / name, "partial");
  EXPECT_EQ(remove_stale_temporaries(dir.path()), 1);
  EXPECT_EQ(entries(dir.path()),
            (std::set<std::string>{live, ".x.tmp.12a.1", "step_0006.vtu", "a.tmp.1.2"}));
}

TEST(AtomicFile, TemporariesWithTheTargetsExtensionAndOfOneTargetOnly) {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  const ScratchDir dir;
  const std::string pid = std::to_string(child);
  const std::string mesh = ".shell.msh.tmp." + pid + ".0.msh",
                    other = ".cube.msh.tmp." + pid + ".4.msh";
  for (const std::string& name : {mesh, other}) write_file_atomically(dir / name, "partial");
  // Only the temporaries of shell.msh: another file's are not this writer's to judge.
  EXPECT_EQ(remove_stale_temporaries(dir.path(), "shell.msh"), 1);
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{other});
  EXPECT_EQ(remove_stale_temporaries(dir.path()), 1);
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(AtomicPath, WriterByNameReplacesTheTargetOnCommitOnly) {
  const ScratchDir dir;
  write_file_atomically(dir / "m.msh", "old");
  {
    AtomicPath file(dir / "m.msh");
    EXPECT_EQ(file.temporary().extension(), ".msh");  // writers that pick the format by name
    EXPECT_EQ(file.temporary().parent_path(), dir.path());
    std::ofstream(file.temporary()) << "new";
    EXPECT_EQ(test::contents(dir / "m.msh"), "old");
    file.commit();
    EXPECT_TRUE(file.temporary().empty());
  }
  EXPECT_EQ(test::contents(dir / "m.msh"), "new");
  {
    AtomicPath abandoned(dir / "m.msh");
    std::ofstream(abandoned.temporary()) << "half";
  }  // a writer that failed: the temporary goes, the target stays
  EXPECT_EQ(test::contents(dir / "m.msh"), "new");
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"m.msh"});
  AtomicPath never_written(dir / "m.msh");
  EXPECT_THROW(never_written.commit(), Error);
  EXPECT_EQ(test::contents(dir / "m.msh"), "new");
}

TEST(AppendFile, AppendsWholeTextsAndReplacesOnlyWhenAsked) {
  const ScratchDir dir;
  write_file_atomically(dir / "a.csv", "x\n1\n");
  {
    AppendFile keep(dir / "a.csv", false);
    keep.append("2\n");
    keep.append("");
    keep.append("3\n");
  }
  EXPECT_EQ(test::contents(dir / "a.csv"), "x\n1\n2\n3\n");
  AppendFile moved = AppendFile(dir / "a.csv", true);  // a new run: starts empty
  moved.append("y\n");
  EXPECT_EQ(test::contents(dir / "a.csv"), "y\n");
  EXPECT_THROW(AppendFile(dir / "missing" / "a.csv", false), Error);
  // A full disk: the write fails with ENOSPC and the file keeps its whole lines.
  if (std::filesystem::exists("/dev/full")) {
    AppendFile full("/dev/full", false);
    try {
      full.append("row\n");
      ADD_FAILURE() << "a write to /dev/full succeeded";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos) << e.what();
    }
  }
}

TEST(AppendFile, CompleteLinesDropsAnUnterminatedRest) {
  EXPECT_EQ(complete_lines("a\nb\nc"), "a\nb\n");
  EXPECT_EQ(complete_lines("a\nb\n"), "a\nb\n");
  EXPECT_EQ(complete_lines("abc"), "");
  EXPECT_EQ(complete_lines(""), "");
}

}  // namespace
}  // namespace plisse
