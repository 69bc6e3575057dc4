// Code that .clang-tidy must refuse: `scripts/tidy --self-test` (CTest clang_tidy) runs clang-tidy
// on this file alone and expects each check named in an `expect:` comment below to report an
// error here. It shows that the checks are on and their warnings are errors; no target builds it.
// Only <utility> is included: the other standard headers would take most of the test's time.
#include <utility>

extern "C" double sqrt(double x);

namespace tidy_findings {

// A value that is not free to copy: its copy constructor counts the copies.
class Text {
 public:
  Text() = default;
  Text(const Text& other) : size_(other.size_), copies_(other.copies_ + 1) {}
  Text(Text&& other) noexcept : size_(other.size_) { other.size_ = 0; }
  Text& operator=(const Text& other) = default;
  Text& operator=(Text&& other) noexcept = default;
  ~Text() = default;
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }

 private:
  int size_ = 0;
  int copies_ = 0;
};

// expect: bugprone-use-after-move
int length_after_move(Text text) {
  const Text taken = std::move(text);
  return text.size() + taken.size();
}

// expect: performance-for-range-copy
int total_length(const Text (&words)[3]) {
  int n = 0;
  for (const Text word : words) n += word.size();
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
bool none(const Text& text) { return text.size() == 0; }

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
