#pragma once
/// Error types and checking macros.
///
/// - `InputError`: bad input (case file, mesh file, command line). Carries the place (file, line,
///   column, key path) and the rule broken; the command line turns it into exit status 2.
/// - `SolverError`: the numerical solution failed (exit status 1, last converged state kept).
/// - `Error`: anything else (a bug or an environment failure).
/// - `PLISSE_CHECK(cond, msg)`: always on, for admissibility of input and files; throws `Error`.
/// - `PLISSE_ASSERT(cond)`: debug builds only, for internal invariants.
#include <sstream>
#include <stdexcept>
#include <string>

namespace plisse {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `text` in single quotes for a message; a text longer than 80 characters is cut to its first 60
/// and its length said ("'abc…' (15000000 characters)"), so that a huge value does not flood the
/// message that names it.
inline std::string quoted_excerpt(const std::string& text) {
  constexpr std::size_t kLongest = 80, kShown = 60;
  if (text.size() <= kLongest) return "'" + text + "'";
  std::size_t cut = kShown;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // UTF-8
  return "'" + text.substr(0, cut) + "…' (" + std::to_string(text.size()) + " characters)";
}

/// Where in the user's input something is. Line and column are 1-based; 0 means unknown.
struct InputPlace {
  std::string file;  ///< file name as given by the user, or "--set" / "command line"
  int line = 0;
  int column = 0;
  std::string key;  ///< dotted key path, e.g. "material.c1" or "boundary[2].surface"
};

class InputError : public Error {
 public:
  InputError(InputPlace place, std::string rule)
      : Error(format(place, rule)), place_(std::move(place)), rule_(std::move(rule)) {}
  const InputPlace& place() const { return place_; }
  const std::string& rule() const { return rule_; }

  /// "file:line:column: key 'a.b': rule" with the parts that are known.
  static std::string format(const InputPlace& place, const std::string& rule) {
    std::ostringstream out;
    if (!place.file.empty()) {
      out << place.file;
      if (place.line > 0) out << ':' << place.line;
      if (place.line > 0 && place.column > 0) out << ':' << place.column;
      out << ": ";
    }
    if (!place.key.empty()) out << "key '" << place.key << "': ";
    out << rule;
    return out.str();
  }

 private:
  InputPlace place_;
  std::string rule_;
};

class SolverError : public Error {
 public:
  using Error::Error;
};

}  // namespace plisse

// msg is a stream chain ("a" << b), not an expression: it cannot be parenthesised.
// NOLINTBEGIN(bugprone-macro-parentheses)
#define PLISSE_CHECK(cond, msg)                   \
  do {                                            \
    if (!(cond)) {                                \
      std::ostringstream check_stream_;           \
      check_stream_ << msg;                       \
      throw ::plisse::Error(check_stream_.str()); \
    }                                             \
  } while (false)
// NOLINTEND(bugprone-macro-parentheses)

#ifdef NDEBUG
#define PLISSE_ASSERT(cond) ((void)0)
#else
#define PLISSE_ASSERT(cond)                                                                      \
  do {                                                                                           \
    if (!(cond))                                                                                 \
      throw ::plisse::Error(std::string("internal error: assertion failed: ") + #cond + " at " + \
                            __FILE__ + ":" + std::to_string(__LINE__));                          \
  } while (false)
#endif
