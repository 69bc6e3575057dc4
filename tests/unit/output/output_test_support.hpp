#pragma once
/// Helpers shared by the output tests: a scratch directory per test, file listing and reading,
/// and the independent Python reader (fixtures/read_output.py, run with Debian's /usr/bin/python3).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

namespace plisse::test {

/// A fresh empty directory under the system's temporary directory, removed with its content.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("plisse-output-" + std::string(info != nullptr ? info->name() : "test") + "-" +
             std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

/// Names of the entries of `dir` (hidden ones included: temporary files start with '.').
inline std::set<std::string> entries(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    names.insert(entry.path().filename().string());
  return names;
}

inline std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs /usr/bin/python3 tests/unit/output/fixtures/SCRIPT ARGS (ARGS already quoted) and returns
/// its JSON output. Fails the test (ADD_FAILURE, returns null) if the script exits with an error.
inline nlohmann::json run_python_fixture(const std::string& script, const std::string& args) {
  const std::string command = std::string("/usr/bin/python3 '") + PLISSE_SOURCE_DIR +
                              "/tests/unit/output/fixtures/" + script + "' " + args;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "cannot run: " << command;
    return nullptr;
  }
  std::string output;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    output.append(buffer, n);
  const int status = ::pclose(pipe);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    ADD_FAILURE() << "'" << command << "' failed (status " << status << "), output: " << output;
    return nullptr;
  }
  return nlohmann::json::parse(output);
}

/// Runs tests/unit/output/fixtures/read_output.py KIND FILE and returns its JSON output. Fails the
/// test (ADD_FAILURE, returns null) if the script exits with an error.
inline nlohmann::json read_with_python(const std::string& kind, const std::filesystem::path& file) {
  return run_python_fixture("read_output.py", kind + " '" + file.string() + "'");
}

/// A float.hex() string from read_output.py back to the double (strtod reads C99 hex floats,
/// inf and nan): exact.
inline double from_hex(const nlohmann::json& text) {
  return std::strtod(text.get<std::string>().c_str(), nullptr);
}

}  // namespace plisse::test
