#include "mesh/gmsh_raw_model.hpp"

#include <cstring>
#include <type_traits>

#include "mesh/isolated_process.hpp"

namespace plisse {
namespace {

constexpr char kMagic[4] = {'P', 'L', 'G', 'M'};
constexpr char kEndMark[4] = {'E', 'N', 'D', '.'};
constexpr std::uint32_t kVersion = 1;

class Writer {
 public:
  explicit Writer(ChildOutput& out) : out_(out) {}
  template <class T>
  void value(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.write(&v, sizeof v);
  }
  template <class T>
  void array(const std::vector<T>& v) {
    value(static_cast<std::uint64_t>(v.size()));
    out_.write(v.data(), v.size() * sizeof(T));
  }
  void string(const std::string& s) {
    value(static_cast<std::uint64_t>(s.size()));
    out_.write(s.data(), s.size());
  }
  void header(GmshReaderReply::Kind kind) {
    out_.write(kMagic, sizeof kMagic);
    value(kVersion);
    value(static_cast<std::uint8_t>(kind));
  }
  void end() { out_.write(kEndMark, sizeof kEndMark); }

 private:
  ChildOutput& out_;
};

/// Bounds-checked reads; `ok()` turns false at the first read past the end and stays false.
class Reader {
 public:
  explicit Reader(std::span<const char> bytes) : bytes_(bytes) {}
  bool ok() const { return ok_; }
  std::size_t left() const { return bytes_.size() - at_; }
  bool raw(void* out, std::size_t n) {
    if (!ok_ || n > left()) return ok_ = false;
    if (n > 0) std::memcpy(out, bytes_.data() + at_, n);
    at_ += n;
    return true;
  }
  template <class T>
  T value() {
    T v{};
    raw(&v, sizeof v);
    return v;
  }
  /// A count of items of `item_bytes` each that must still fit in the message.
  std::size_t count(std::size_t item_bytes) {
    const auto n = value<std::uint64_t>();
    if (!ok_ || (item_bytes > 0 && n > left() / item_bytes)) {
      ok_ = false;
      return 0;
    }
    return static_cast<std::size_t>(n);
  }
  template <class T>
  void array(std::vector<T>& v) {
    v.resize(count(sizeof(T)));
    raw(v.data(), v.size() * sizeof(T));
  }
  void string(std::string& s) {
    s.resize(count(1));
    raw(s.data(), s.size());
  }
  bool mark(const char (&expected)[4]) {
    char got[4] = {};
    return raw(got, sizeof got) && std::memcmp(got, expected, sizeof got) == 0;
  }

 private:
  std::span<const char> bytes_;
  std::size_t at_ = 0;
  bool ok_ = true;
};

// Smallest encoded size of one item of each list, so that counts are checked against the bytes
// left before anything is allocated.
constexpr std::size_t kMinTypeBytes = 4 + 4 + 8;
constexpr std::size_t kMinBlockBytes = 4 + 8 + 8;
constexpr std::size_t kMinGroupBytes = 4 + 4 + 8 + 8;
constexpr std::size_t kMinGroupElementsBytes = 4 + 8;

}  // namespace

void send_model(const RawGmshModel& model, ChildOutput& out) {
  static_assert(sizeof(std::size_t) == sizeof(std::uint64_t));
  Writer w(out);
  w.header(GmshReaderReply::Kind::model);
  w.value(static_cast<std::uint64_t>(model.types.size()));
  for (const auto& t : model.types) {
    w.value(static_cast<std::int32_t>(t.type));
    w.value(static_cast<std::int32_t>(t.dim));
    w.string(t.name);
  }
  w.array(model.node_tags);
  w.array(model.coordinates);
  w.value(static_cast<std::uint64_t>(model.blocks.size()));
  for (const auto& b : model.blocks) {
    w.value(static_cast<std::int32_t>(b.type));
    w.array(b.element_tags);
    w.array(b.node_tags);
  }
  w.value(static_cast<std::uint64_t>(model.groups.size()));
  for (const auto& g : model.groups) {
    w.value(static_cast<std::int32_t>(g.dim));
    w.value(static_cast<std::int32_t>(g.tag));
    w.string(g.name);
    w.value(static_cast<std::uint64_t>(g.elements.size()));
    for (const auto& e : g.elements) {
      w.value(static_cast<std::int32_t>(e.type));
      w.array(e.element_tags);
    }
  }
  w.end();
}

void send_error(const std::string& rule, ChildOutput& out) {
  Writer w(out);
  w.header(GmshReaderReply::Kind::error);
  w.string(rule);
  w.end();
}

void send_out_of_memory(ChildOutput& out) {
  Writer w(out);
  w.header(GmshReaderReply::Kind::out_of_memory);
  w.end();
}

bool decode_reply(std::span<const char> bytes, GmshReaderReply& reply) {
  Reader r(bytes);
  if (!r.mark(kMagic) || r.value<std::uint32_t>() != kVersion) return false;
  const auto kind = r.value<std::uint8_t>();
  reply = GmshReaderReply{};
  switch (kind) {
    case static_cast<std::uint8_t>(GmshReaderReply::Kind::model): {
      reply.kind = GmshReaderReply::Kind::model;
      RawGmshModel& m = reply.model;
      m.types.resize(r.count(kMinTypeBytes));
      for (auto& t : m.types) {
        t.type = r.value<std::int32_t>();
        t.dim = r.value<std::int32_t>();
        r.string(t.name);
      }
      r.array(m.node_tags);
      r.array(m.coordinates);
      m.blocks.resize(r.count(kMinBlockBytes));
      for (auto& b : m.blocks) {
        b.type = r.value<std::int32_t>();
        r.array(b.element_tags);
        r.array(b.node_tags);
      }
      m.groups.resize(r.count(kMinGroupBytes));
      for (auto& g : m.groups) {
        g.dim = r.value<std::int32_t>();
        g.tag = r.value<std::int32_t>();
        r.string(g.name);
        g.elements.resize(r.count(kMinGroupElementsBytes));
        for (auto& e : g.elements) {
          e.type = r.value<std::int32_t>();
          r.array(e.element_tags);
        }
      }
      break;
    }
    case static_cast<std::uint8_t>(GmshReaderReply::Kind::error):
      reply.kind = GmshReaderReply::Kind::error;
      r.string(reply.rule);
      break;
    case static_cast<std::uint8_t>(GmshReaderReply::Kind::out_of_memory):
      reply.kind = GmshReaderReply::Kind::out_of_memory;
      break;
    default:
      return false;
  }
  return r.mark(kEndMark) && r.left() == 0 && r.ok();
}

}  // namespace plisse
