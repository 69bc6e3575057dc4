#include "output/run_log.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "core/error.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::contents;
using test::entries;
using test::ScratchDir;

TEST(RunLog, EchoesToTerminalStreamsAndWritesTimedLinesOnFlush) {
  const ScratchDir dir;
  std::ostringstream out, err;
  const auto path = dir / "log.txt";
  {
    RunLog log(path, &out, &err);
    log.info("step 1 converged in 4 iterations");
    log.warn("negative pivots: 3");
    EXPECT_FALSE(std::filesystem::exists(path));  // written on flush only
    log.flush();
    EXPECT_NE(contents(path).find("] warning: negative pivots: 3\n"), std::string::npos);
    log.error("Newton diverged\nlast converged step kept");
  }  // destructor flushes
  EXPECT_EQ(out.str(), "step 1 converged in 4 iterations\n");
  EXPECT_EQ(
      err.str(),
      "warning: negative pivots: 3\nerror: Newton diverged\nerror: last converged step kept\n");

  const std::string text = contents(path);
  const std::regex line(R"(\[ *[0-9]+\.[0-9]s\] (.*))");
  std::vector<std::string> messages;
  std::istringstream lines(text);
  for (std::string l; std::getline(lines, l);) {
    std::smatch match;
    ASSERT_TRUE(std::regex_match(l, match, line)) << l;
    EXPECT_EQ(l.find("[   "), 0u) << "width 7 for the seconds: " << l;
    messages.push_back(match[1]);
  }
  EXPECT_EQ(messages, (std::vector<std::string>{
                          "step 1 converged in 4 iterations", "warning: negative pivots: 3",
                          "error: Newton diverged", "error: last converged step kept"}));
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"log.txt"});
}

TEST(RunLog, FlushWritesEverythingSoFar) {
  const ScratchDir dir;
  RunLog log(dir / "log.txt", nullptr, nullptr);
  log.info("a");
  log.flush();
  const std::string first = contents(dir / "log.txt");
  log.info("b");
  log.flush();
  const std::string second = contents(dir / "log.txt");
  EXPECT_EQ(second.substr(0, first.size()), first);  // earlier lines kept, new one appended
  EXPECT_EQ(log.lines().size(), 2u);
  EXPECT_EQ(log.lines()[1].substr(log.lines()[1].size() - 1), "b");
  EXPECT_GE(log.elapsed_seconds(), 0.0);
}

TEST(RunLog, TerminalOnlyLogWritesNoFile) {
  const ScratchDir dir;
  std::ostringstream out;
  RunLog log({}, &out, &out);
  log.info("checked");
  log.flush();
  EXPECT_EQ(out.str(), "checked\n");
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(RunLog, FlushesAppendToOneFileAndAResumedLogContinuesTheEarlierOne) {
  const ScratchDir dir;
  const auto path = dir / "log.txt";
  {
    RunLog log(path, nullptr, nullptr);
    log.info("first run");
    log.flush();
  }
  struct stat before {};
  ASSERT_EQ(::stat(path.c_str(), &before), 0);
  // A killed run may leave its last line unterminated; the resumed log starts on a new line.
  { std::ofstream(path, std::ios::app) << "[   9.9s] half a li"; }
  {
    RunLog log(path, nullptr, nullptr, LogStart::append);
    log.info("resumed");
  }
  struct stat after {};
  ASSERT_EQ(::stat(path.c_str(), &after), 0);
  EXPECT_EQ(before.st_ino, after.st_ino);
  const std::string text = contents(path);
  EXPECT_EQ(text.find("] first run\n"), 9u) << text;
  EXPECT_NE(text.find("half a li\n["), std::string::npos) << text;
  EXPECT_EQ(text.substr(text.size() - 8), "resumed\n") << text;
  {
    RunLog log(path, nullptr, nullptr);  // a new run: the earlier lines go
    log.info("new");
  }
  EXPECT_EQ(contents(path).find("first run"), std::string::npos);
}

}  // namespace
}  // namespace plisse
