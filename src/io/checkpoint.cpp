#include "io/checkpoint.hpp"

#include <bit>
#include <cstring>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace plisse {
namespace {

static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian");

constexpr char kMagic[8] = {'P', 'L', 'I', 'S', 'S', 'E', 'C', 'K'};
constexpr char kTrailer[8] = {'E', 'N', 'D', 'C', 'K', 'P', 'T', '1'};
// 2: negative_pivots after the term states; 3: the element family after the fingerprint
constexpr std::uint32_t kVersion = 3;

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
  void raw(const char* p, size_t n) { bytes_.append(p, n); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  Reader(std::string bytes, std::filesystem::path path)
      : bytes_(std::move(bytes)), path_(std::move(path)) {}
  template <class T>
  T value() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::vector<double> doubles() {
    const auto n = value<std::uint64_t>();
    if (n > (bytes_.size() - at_) / sizeof(double)) fail("truncated or corrupt (array too long)");
    std::vector<double> v(n);
    if (n > 0)
      std::memcpy(v.data(), bytes_.data() + at_, n * sizeof(double));  // data() may be null
    at_ += n * sizeof(double);
    return v;
  }
  bool raw_equals(const char* p, size_t n) {
    need(n);
    const bool same = std::memcmp(bytes_.data() + at_, p, n) == 0;
    at_ += n;
    return same;
  }
  bool at_end() const { return at_ == bytes_.size(); }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError({path_.string(), 0, 0, "--resume"}, "not a usable plisse checkpoint: " + why);
  }

 private:
  void need(size_t n) const {
    if (bytes_.size() - at_ < n) fail("truncated");
  }
  std::string bytes_;
  std::filesystem::path path_;
  size_t at_ = 0;
};

}  // namespace

std::uint64_t case_fingerprint(const std::filesystem::path& case_file,
                               const std::vector<std::string>& overrides) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](std::string_view bytes) {
    for (unsigned char c : bytes) {
      h ^= c;
      h *= 1099511628211ull;
    }
    h ^= 0xff;  // separator, so ("ab", "c") and ("a", "bc") differ
    h *= 1099511628211ull;
  };
  mix(read_file(case_file));
  for (const auto& o : overrides) mix(o);
  return h;
}

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& c) {
  Writer w;
  w.raw(kMagic, sizeof kMagic);
  w.value(kVersion);
  w.value(c.case_fingerprint);
  w.value<std::uint32_t>(c.element == ElementFamily::mini ? 0 : 1);
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
  w.raw(kTrailer, sizeof kTrailer);
  write_file_atomically(path, w.bytes());
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError({path.string(), 0, 0, "--resume"}, "no checkpoint.bin in the run directory");
  Reader r(read_file(path), path);
  if (!r.raw_equals(kMagic, sizeof kMagic)) r.fail("wrong file type");
  if (r.value<std::uint32_t>() != kVersion) r.fail("written by another version of plisse");
  Checkpoint c;
  c.case_fingerprint = r.value<std::uint64_t>();
  const auto element = r.value<std::uint32_t>();
  if (element > 1) r.fail("unknown element family");
  c.element = element == 0 ? ElementFamily::mini : ElementFamily::taylor_hood;
  c.steps = static_cast<int>(r.value<std::int64_t>());
  c.time = r.value<double>();
  c.dt = r.value<double>();
  c.previous_dt = r.value<double>();
  c.previous_state = r.doubles();
  c.state = r.doubles();
  c.bubbles = r.doubles();
  const auto n_terms = r.value<std::uint64_t>();
  if (n_terms > 1000000) r.fail("corrupt term count");
  for (std::uint64_t k = 0; k < n_terms; ++k) c.term_states.push_back(r.doubles());
  c.negative_pivots = static_cast<int>(r.value<std::int64_t>());
  if (!r.raw_equals(kTrailer, sizeof kTrailer) || !r.at_end()) r.fail("truncated or corrupt");
  return c;
}

}  // namespace plisse
