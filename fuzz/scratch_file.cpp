#include "scratch_file.hpp"

#include <unistd.h>

#include <fstream>
#include <system_error>

namespace plisse::fuzz {
namespace {

/// The per-process directory; removed by its destructor at normal exit.
class ScratchDirectory {
 public:
  ScratchDirectory()
      : path_(std::filesystem::temp_directory_path() /
              ("plisse-fuzz-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

std::filesystem::path write_scratch_file(const std::string& name, Bytes data) {
  static const ScratchDirectory directory;
  const std::filesystem::path path = directory.path() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
  out.close();
  if (!out) throw Finding("fuzz: cannot write the scratch file " + path.string());
  return path;
}

}  // namespace plisse::fuzz
