#pragma once
/// FNV-1a, 64 bit (Fowler, Noll, Vo): a fast hash of bytes for fingerprints and checksums. It
/// detects damage and differences, not tampering.
#include <cstddef>
#include <cstdint>

namespace plisse {

class Fnv1a {
 public:
  void add(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) hash_ = (hash_ ^ p[i]) * 1099511628211ull;
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 1469598103934665603ull;
};

}  // namespace plisse
