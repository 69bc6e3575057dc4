#include "output/checkpoint.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
#include "core/fnv1a.hpp"
#include "core/input_file.hpp"
#include "mesh/topology.hpp"
#include "output/atomic_file.hpp"

namespace plisse {
namespace {

static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian");

constexpr char kMagic[8] = {'P', 'L', 'I', 'S', 'S', 'E', 'C', 'K'};
constexpr char kTrailer[8] = {'E', 'N', 'D', 'C', 'K', 'P', 'T', '1'};
// 2: negative_pivots after the term states; 3: the element family after the fingerprint;
// 4: the fingerprint's parts (case text, --set values, mesh file) and a checksum before the
// trailer; 5: the geometry hash of the mesh solved on, after the mesh file's
constexpr std::uint32_t kVersion = 5;
// The element family's code: 0 MINI, 1 Taylor-Hood (since version 3), 2 the shell triangle (a
// code added within version 5: earlier files hold 0 or 1 and read the same).
constexpr std::array<ElementFamily, 3> kElementOfCode = {
    ElementFamily::mini, ElementFamily::taylor_hood, ElementFamily::shell};
constexpr std::uint64_t kMaxStrings = 100000;          // --set values in a fingerprint
constexpr std::uint64_t kMaxStringBytes = 1ull << 20;  // one --set value or path
constexpr std::int64_t kMaxSteps = 1000000000;

/// The code of `family` in kElementOfCode.
std::uint32_t element_code(ElementFamily family) {
  const auto it = std::find(kElementOfCode.begin(), kElementOfCode.end(), family);
  PLISSE_CHECK(it != kElementOfCode.end(), "checkpoint: element family without a code");
  return static_cast<std::uint32_t>(it - kElementOfCode.begin());
}

/// FNV-1a of a file's bytes, read in chunks (a mesh file may be large).
std::uint64_t hash_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path.string(), 0, 0, ""}, "cannot read the file");
  Fnv1a hash;
  std::vector<char> chunk(1 << 16);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    hash.add(chunk.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError({path.string(), 0, 0, ""}, "cannot read the file");
  return hash.value();
}

class Writer {
 public:
  template <class T>
  void value(const T& v) {
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes_.append(p, sizeof(T));
  }
  void doubles(const std::vector<double>& v) {
    value<std::uint64_t>(v.size());
    if (!v.empty())
      bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
  void text(const std::string& t) {
    value<std::uint64_t>(t.size());
    bytes_.append(t);
  }
  void raw(const char* p, size_t n) { bytes_.append(p, n); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  Reader(std::string bytes, std::filesystem::path path)
      : bytes_(std::move(bytes)), path_(std::move(path)), end_(bytes_.size()) {}
  template <class T>
  T value() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  /// An array of finite values (`what` names it in the message).
  std::vector<double> doubles(const char* what) {
    const auto n = value<std::uint64_t>();
    if (n > (end_ - at_) / sizeof(double)) fail(std::string(what) + ": array too long");
    std::vector<double> v(n);
    if (n > 0)
      std::memcpy(v.data(), bytes_.data() + at_, n * sizeof(double));  // data() may be null
    at_ += n * sizeof(double);
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i]))
        fail(std::string(what) + ": value " + std::to_string(i) + " is not finite");
    return v;
  }
  std::string text(const char* what) {
    const auto n = value<std::uint64_t>();
    if (n > kMaxStringBytes || n > end_ - at_) fail(std::string(what) + ": text too long");
    std::string t(bytes_.data() + at_, n);
    at_ += n;
    return t;
  }
  /// The content ends before the checksum and trailer; checks both. Call first.
  void check_frame() {
    const std::size_t tail = sizeof(std::uint64_t) + sizeof kTrailer;
    if (bytes_.size() < sizeof kMagic + tail) fail("truncated");
    if (std::memcmp(bytes_.data() + bytes_.size() - sizeof kTrailer, kTrailer, sizeof kTrailer) !=
        0)
      fail("truncated (no end marker)");
    end_ = bytes_.size() - tail;
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes_.data() + end_, sizeof stored);
    Fnv1a hash;
    hash.add(bytes_.data(), end_);
    if (hash.value() != stored) fail("damaged: its checksum does not match its content");
  }
  bool raw_equals(const char* p, std::size_t n) {
    need(n);
    const bool same = std::memcmp(bytes_.data() + at_, p, n) == 0;
    at_ += n;
    return same;
  }
  bool at_end() const { return at_ == end_; }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError({path_.string(), 0, 0, "--resume"}, "not a usable plisse checkpoint: " + why);
  }

 private:
  void need(std::size_t n) const {
    if (end_ - at_ < n) fail("truncated");
  }
  std::string bytes_;
  std::filesystem::path path_;
  std::size_t at_ = 0;
  std::size_t end_;  ///< where the content ends (check_frame)
};

}  // namespace

RunFingerprint run_fingerprint(const std::filesystem::path& case_file,
                               const std::vector<std::string>& overrides,
                               const std::string& mesh_file, const Mesh& mesh) {
  RunFingerprint f;
  f.case_text = hash_file(case_file);
  f.overrides = overrides;
  if (!mesh_file.empty()) {
    f.mesh_file = std::filesystem::absolute(mesh_file).lexically_normal().string();
    f.mesh_bytes = hash_file(mesh_file);
  }
  f.geometry = geometry_hash(mesh);
  return f;
}

std::string fingerprint_changes(const RunFingerprint& saved, const RunFingerprint& now) {
  const auto list = [](const std::vector<std::string>& values) {
    std::string text;
    for (const auto& v : values) text += (text.empty() ? "" : ", ") + v;
    return text.empty() ? std::string("none") : text;
  };
  std::vector<std::string> changes;
  if (saved.case_text != now.case_text)
    changes.push_back("the case file changed since the checkpoint was written");
  if (saved.overrides != now.overrides)
    changes.push_back("the --set values differ (checkpoint: " + list(saved.overrides) +
                      "; now: " + list(now.overrides) + ")");
  // The mesh file is judged by its bytes, not by how its path is spelled: the same file named
  // relative to another working directory, by its absolute path or through `..` is the same mesh.
  if (saved.mesh_file.empty() != now.mesh_file.empty())
    changes.push_back("the mesh differs (checkpoint: " +
                      (saved.mesh_file.empty() ? "generated" : saved.mesh_file) +
                      "; now: " + (now.mesh_file.empty() ? "generated" : now.mesh_file) + ")");
  else if (saved.mesh_bytes != now.mesh_bytes)
    changes.push_back(saved.mesh_file == now.mesh_file
                          ? "the mesh file " + now.mesh_file +
                                " changed since the checkpoint was written"
                          : "the mesh file's content differs from the checkpoint's (checkpoint: " +
                                saved.mesh_file + "; now: " + now.mesh_file + ")");
  else if (saved.geometry != now.geometry)
    changes.push_back(
        "the mesh's nodes or tetrahedra differ from the checkpoint's (a changed imperfection, its "
        "mode file, or the mesh generator)");
  std::string text;
  for (const auto& c : changes) text += (text.empty() ? "" : "; ") + c;
  return text;
}

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& c) {
  Writer w;
  w.raw(kMagic, sizeof kMagic);
  w.value(kVersion);
  w.value(c.fingerprint.case_text);
  w.value<std::uint64_t>(c.fingerprint.overrides.size());
  for (const auto& o : c.fingerprint.overrides) w.text(o);
  w.text(c.fingerprint.mesh_file);
  w.value(c.fingerprint.mesh_bytes);
  w.value(c.fingerprint.geometry);
  w.value<std::uint32_t>(element_code(c.element));
  w.value<std::int64_t>(c.steps);
  w.value(c.time);
  w.value(c.dt);
  w.value(c.previous_dt);
  w.doubles(c.previous_state);
  w.doubles(c.state);
  w.doubles(c.bubbles);
  w.value<std::uint64_t>(c.term_states.size());
  for (const auto& t : c.term_states) w.doubles(t);
  w.value<std::int64_t>(c.negative_pivots);
  Fnv1a checksum;
  checksum.add(w.bytes().data(), w.bytes().size());
  w.value(checksum.value());
  w.raw(kTrailer, sizeof kTrailer);
  write_file_atomically(path, w.bytes());
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw InputError({path.string(), 0, 0, "--resume"}, "no checkpoint.bin in the run directory");
  std::string bytes;
  try {
    // The file type and version first, from the first bytes: a large file of another kind is
    // refused unread.
    // (A file that is not regular, or too short, is left to read_file's and the reader's checks.)
    std::array<char, sizeof kMagic + sizeof kVersion> first{};
    std::ifstream head;
    if (std::filesystem::is_regular_file(path, error)) head.open(path, std::ios::binary);
    if (head.is_open() && head.read(first.data(), first.size())) {
      std::uint32_t version = 0;
      std::memcpy(&version, first.data() + sizeof kMagic, sizeof version);
      if (std::memcmp(first.data(), kMagic, sizeof kMagic) != 0)
        throw InputError({path.string(), 0, 0, ""},
                         "not a usable plisse checkpoint: wrong file type");
      if (version != kVersion)
        throw InputError({path.string(), 0, 0, ""},
                         "not a usable plisse checkpoint: written by another version of plisse");
    }
    // Reading holds the file and then its arrays: a checkpoint larger than a third of the memory
    // this process may use cannot be a state it could have written and continue.
    bytes = read_file(path, physical_memory_bytes() / 3);
  } catch (const InputError& e) {
    throw InputError({path.string(), 0, 0, "--resume"}, e.rule());
  }
  Reader r(std::move(bytes), path);
  if (!r.raw_equals(kMagic, sizeof kMagic)) r.fail("wrong file type");
  if (r.value<std::uint32_t>() != kVersion) r.fail("written by another version of plisse");
  r.check_frame();
  Checkpoint c;
  c.fingerprint.case_text = r.value<std::uint64_t>();
  const auto n_overrides = r.value<std::uint64_t>();
  if (n_overrides > kMaxStrings) r.fail("too many --set values");
  for (std::uint64_t k = 0; k < n_overrides; ++k)
    c.fingerprint.overrides.push_back(r.text("--set value"));
  c.fingerprint.mesh_file = r.text("mesh file");
  c.fingerprint.mesh_bytes = r.value<std::uint64_t>();
  c.fingerprint.geometry = r.value<std::uint64_t>();
  const auto element = r.value<std::uint32_t>();
  if (element >= kElementOfCode.size()) r.fail("unknown element family");
  c.element = kElementOfCode[element];
  const auto steps = r.value<std::int64_t>();
  if (steps < 0 || steps > kMaxSteps)
    r.fail("step count " + std::to_string(steps) + " out of range");
  c.steps = static_cast<int>(steps);
  c.time = r.value<double>();
  c.dt = r.value<double>();
  c.previous_dt = r.value<double>();
  if (!std::isfinite(c.time) || c.time < 0.0) r.fail("time is not finite and >= 0");
  if (!std::isfinite(c.dt) || c.dt <= 0.0) r.fail("next step size is not finite and > 0");
  if (!std::isfinite(c.previous_dt) || c.previous_dt < 0.0)
    r.fail("last step size is not finite and >= 0");
  c.previous_state = r.doubles("previous state");
  c.state = r.doubles("state");
  if (c.state.empty()) r.fail("the state is empty");
  if (!c.previous_state.empty() && c.previous_state.size() != c.state.size())
    r.fail("the previous state has " + std::to_string(c.previous_state.size()) +
           " values for a state of " + std::to_string(c.state.size()));
  c.bubbles = r.doubles("element state");
  const auto n_terms = r.value<std::uint64_t>();
  if (n_terms > 1000000) r.fail("corrupt term count");
  for (std::uint64_t k = 0; k < n_terms; ++k) c.term_states.push_back(r.doubles("term state"));
  const auto negative_pivots = r.value<std::int64_t>();
  if (negative_pivots < -1 || negative_pivots > std::int64_t{1} << 40)
    r.fail("negative pivot count out of range");
  c.negative_pivots = static_cast<int>(negative_pivots);
  if (!r.at_end()) r.fail("unexpected bytes after the last field");
  return c;
}

}  // namespace plisse
