// libFuzzer entry point; PLISSE_FUZZ_TARGET names the target function of targets.hpp (set per
// executable in fuzz/CMakeLists.txt). An exception other than plisse::Error escaping the target
// is a finding: it is reported with its type and message, then abort() lets libFuzzer save the
// input.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <typeinfo>

#include "targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    plisse::fuzz::PLISSE_FUZZ_TARGET(plisse::fuzz::Bytes(data, size));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plisse fuzz finding: %s escaped: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "plisse fuzz finding: an exception of unknown type escaped\n");
    std::abort();
  }
  return 0;
}
