// Code that .clang-tidy must refuse: `scripts/tidy --self-test` (CTest clang_tidy) runs clang-tidy
// on this file alone and expects each check named in an `expect:` comment below to report an
// error here. It shows that the checks are on and their warnings are errors; no target builds it.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace tidy_findings {

// expect: bugprone-use-after-move
std::size_t length_after_move(std::string text) {
  const std::string taken = std::move(text);
  return text.size() + taken.size();
}

// expect: performance-for-range-copy
std::size_t total_length(const std::vector<std::string>& words) {
  std::size_t n = 0;
  for (const std::string word : words) n += word.size();
  return n;
}

// expect: bugprone-narrowing-conversions
float to_single(double x) {
  float y = 0.0F;
  y += x;
  return y;
}

// expect: performance-type-promotion-in-math-fn
float root(float x) { return ::sqrt(x); }

// expect: modernize-use-nullptr
const int* no_value() { return 0; }

// expect: readability-container-size-empty
bool none(const std::vector<double>& values) { return values.size() == 0; }

// expect: google-explicit-constructor
struct Millimetres {
  Millimetres(double v) : value(v) {}
  double value;
};

// expect: clang-analyzer-core.DivideZero
int divide_by_zero(int n) {
  int zero = 0;
  return n / zero;
}

}  // namespace tidy_findings
