// The bad-input guarantee (docs/architecture.md, "Interface contract"; tests/bad-inputs/README.md):
// for every corpus file, `plisse check` and `plisse run -o <fresh dir>` both
//   - exit with status 2 (bad input), not by a signal, within 30 s;
//   - print a message that names the file (and line/column when the error is in the YAML), the
//     key and the broken rule, i.e. every fragment of the file's header;
//   - show no trace of a crash ("terminate called", "Segmentation", sanitizer reports);
//   - and `plisse run` leaves no run directory behind (an existing -o path is left unchanged).
// check and run of one entry run at the same time, so the corpus takes about one plisse start-up
// (~0.3 s) per entry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "corpus_entry.hpp"
#include "support/run_plisse.hpp"

namespace plisse::test {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kCorpus{
#include "bad_inputs_corpus.inc"
};

// Above the Gmsh reader's CPU-time limit for a small file (10 s, mesh/gmsh_io.hpp): a crafted file
// on which Gmsh loops is stopped there and refused, in time.
constexpr double kTimeLimitSeconds = 30.0;

/// Texts that only appear when plisse crashed or a sanitizer caught something.
const std::vector<std::string> kCrashSigns{"terminate called", "Segmentation",  "Sanitizer",
                                           "runtime error:",   "core dumped",   "Aborted",
                                           "internal error",   "std::bad_alloc"};

const fs::path kCorpusDir = PLISSE_BAD_INPUTS_DIR;

std::string test_name(const std::string& file) {
  std::string name = fs::path(file).stem().string();
  std::replace_if(
      name.begin(), name.end(),
      [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  return name;
}

/// What a path looked like, to tell whether a failed run changed it.
struct PathState {
  bool exists = false;
  bool is_directory = false;
  std::uintmax_t size = 0;
  fs::file_time_type modified{};
  bool operator==(const PathState&) const = default;
};

PathState state_of(const fs::path& p) {
  PathState s;
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(p, ec);
  s.exists = fs::exists(status);
  if (!s.exists) return s;
  s.is_directory = fs::is_directory(status);
  if (!s.is_directory) s.size = fs::file_size(p, ec);
  s.modified = fs::last_write_time(p, ec);
  return s;
}

std::vector<std::string> arguments(const std::string& command, const CorpusEntry& entry,
                                   const std::string& case_file, const std::string& output,
                                   const fs::path& work) {
  std::vector<std::string> args{command, case_file};
  if (command == "run") {
    args.push_back("-o");
    args.push_back(output);
  }
  for (const std::string& a : entry.args) args.push_back(expand(a, entry, work));
  return args;
}

class BadInput : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInput, IsRefusedWithALocatedMessageAndNoOutput) {
  const CorpusEntry entry = read_corpus_entry(kCorpusDir / GetParam());
  if (!entry.known_bug.empty()) GTEST_SKIP() << "known bug: " << entry.known_bug;
  if (kAddressSanitizer && !entry.not_under_asan.empty())
    GTEST_SKIP() << "not under AddressSanitizer: " << entry.not_under_asan;
  const fs::path root = scratch_directory("bad-inputs/" + test_name(GetParam()));
  const fs::path work = root / "work";  // the working directory: must stay empty
  fs::create_directories(work);
  const std::string case_file = expand(entry.case_path, entry, work);
  const std::string output = expand(entry.output, entry, work);
  const PathState output_before = state_of(output);
  SCOPED_TRACE(entry.file.string() + ": " + entry.description);

  const std::string plisse = std::string(PLISSE_BINARY_DIR) + "/bin/plisse";
  std::vector<std::unique_ptr<ChildProcess>> children;
  for (const std::string& command : entry.commands)
    children.push_back(
        std::make_unique<ChildProcess>(plisse, arguments(command, entry, case_file, output, work),
                                       work, root / (command + ".log")));

  for (std::size_t i = 0; i < children.size(); ++i) {
    const std::string& command = entry.commands[i];
    const ChildResult r = children[i]->wait(kTimeLimitSeconds);
    SCOPED_TRACE("plisse " + command + " said:\n" + r.output);
    EXPECT_FALSE(r.timed_out) << "plisse " << command << " did not finish within "
                              << kTimeLimitSeconds << " s";
    EXPECT_EQ(r.signal, 0) << "plisse " << command << " was killed by signal " << r.signal;
    EXPECT_TRUE(r.exited && r.status == 2)
        << "plisse " << command << ": expected exit status 2 (bad input), got " << r.status;
    for (const std::string& sign : kCrashSigns)
      EXPECT_EQ(r.output.find(sign), std::string::npos) << "crash sign '" << sign << "'";
    EXPECT_NE(r.output.find("plisse: error: "), std::string::npos) << "no error message";
    if (!names_other_file(entry)) {
      EXPECT_NE(r.output.find(case_file), std::string::npos) << "the case file is not named";
    }
    for (const std::string& fragment : entry.expect) {
      const std::string text = expected_text(fragment, entry, case_file, work);
      EXPECT_NE(r.output.find(text), std::string::npos) << "missing '" << text << "'";
    }
    EXPECT_LT(r.seconds, kTimeLimitSeconds);
  }

  EXPECT_TRUE(fs::is_empty(work)) << "plisse left files in its working directory " << work;
  EXPECT_TRUE(state_of(output) == output_before)
      << "plisse run created or changed its output path " << output;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(kCorpus),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return test_name(info.param);
                         });

TEST(BadInputCorpus, HasAtLeastFiftyEntriesEachWithAHeaderAndARule) {
  EXPECT_GE(kCorpus.size(), 50u);
  for (const std::string& file : kCorpus) {
    const CorpusEntry entry = read_corpus_entry(kCorpusDir / file);  // throws on a bad header
    const bool has_rule = std::any_of(entry.expect.begin(), entry.expect.end(), [](const auto& f) {
      return f.rfind("line ", 0) != 0 && f.rfind("file ", 0) != 0;
    });
    EXPECT_TRUE(has_rule) << file << ": the header expects no rule fragment";
  }
}

TEST(BadInputCorpus, FolderMatchesTheListTheTestWasBuiltWith) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(kCorpusDir))
    if (e.path().extension() == ".yaml") files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, kCorpus) << "re-run CMake (the corpus changed since the test was configured)";
}

}  // namespace
}  // namespace plisse::test
