#pragma once
/// Reading the XML of plisse's VTU and PVTU files (internal to src/output; vtu_reader.cpp uses
/// it): a file opened for bounded reads whose errors name it, and the tags of its XML header.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "core/input_file.hpp"

namespace plisse::vtu_detail {

/// One XML tag: its name, whether it closes an element, and its attributes (entities decoded).
struct Tag {
  std::string name;
  bool closing = false;
  std::map<std::string, std::string> attributes;
};

/// A VTU or PVTU file opened for reading: its size is known (and refused when above half the
/// machine's memory), reads are checked against it, and every error names the file.
class VtuFile {
 public:
  /// `kind` starts every error message ("VTU", "PVTU").
  explicit VtuFile(std::filesystem::path path, std::string kind = "VTU")
      : path_(std::move(path)), kind_(std::move(kind)) {
    std::error_code ec;
    const auto status = std::filesystem::status(path_, ec);
    if (ec || !std::filesystem::exists(status)) fail("cannot open: no such file");
    if (!std::filesystem::is_regular_file(status)) fail("cannot open: not a regular file");
    in_.open(path_, std::ios::binary);
    if (!in_) fail("cannot open for reading");
    in_.seekg(0, std::ios::end);
    const std::streamoff end = in_.tellg();
    if (end < 0) fail("cannot determine the file size");
    size_ = static_cast<std::uint64_t>(end);
    // Its blocks are read whole into memory: a file beyond half the machine's memory (a sparse
    // file, or not one of plisse's) is refused before any block is allocated.
    const std::uint64_t memory = physical_memory_bytes();
    if (size_ > memory / 2)
      fail("is " + std::to_string(size_ >> 20) + " MiB, more than half of this machine's memory (" +
           std::to_string(memory >> 20) + " MiB): too large to read");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(kind_ + " '" + path_.string() + "': " + what);
  }

  std::uint64_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }

  /// Reads n bytes at pos; pos + n <= size() is checked first.
  void read_at(std::uint64_t pos, void* out, std::uint64_t n) {
    if (pos > size_ || n > size_ - pos) fail("truncated: a read past the end of the file");
    if (n == 0) return;  // out may be the null data() of an empty vector
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(pos));
    in_.read(static_cast<char*>(out), static_cast<std::streamsize>(n));
    if (static_cast<std::uint64_t>(in_.gcount()) != n)
      fail("read error (file changed while read?)");
  }

  std::string read_string(std::uint64_t pos, std::uint64_t n) {
    std::string s(static_cast<std::size_t>(n), '\0');
    read_at(pos, s.data(), n);
    return s;
  }

 private:
  std::filesystem::path path_;
  std::string kind_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
};

/// XML whitespace.
bool is_space(char c);
/// A decimal unsigned integer that fills `text`, else nullopt.
std::optional<std::uint64_t> parse_unsigned(std::string_view text);
/// Decodes the five predefined XML entities; nullopt for any other '&' sequence.
std::optional<std::string> decode_entities(std::string_view text);
/// Parses the inside of one tag, text between '<' and '>' (file.fail on malformed XML).
Tag parse_tag(const VtuFile& file, std::string_view text);
/// The attribute `key` of `tag`, or nullptr.
const std::string* attribute(const Tag& tag, const std::string& key);
/// The attribute `key` of `tag`; file.fail when it is missing.
std::string require_attribute(const VtuFile& file, const Tag& tag, const std::string& key);
/// The attribute `key` of `tag` as an unsigned integer; file.fail otherwise.
std::uint64_t require_unsigned(const VtuFile& file, const Tag& tag, const std::string& key);

}  // namespace plisse::vtu_detail
