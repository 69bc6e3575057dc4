#pragma once
/// The claims of docs/validation.md and docs/verification.md, asserted and recorded in one call.
///
/// A row of those pages compares what plisse measured with an external reference (a closed form,
/// a published law, an experiment, another code) and claims that their difference lies in a band.
/// `expect_claim` asserts that band and, when the environment variable PLISSE_VALIDATION_RECORD
/// names a file, appends the row to it as one line of JSON; scripts/validate runs the tests of a
/// tier with it set and writes the pages' generated tables from those lines. So the number a page
/// prints, the band it claims and the band a test asserts are one value each (docs/validation.md,
/// "How the tables are made").
///
/// A regression guard compares plisse with an earlier run of plisse rather than with an external
/// reference: `Claim::kind = ClaimKind::regression`, printed apart from the validation rows.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

// The tier a validation test is built for (tests/CMakeLists.txt, DEFINITIONS): 0 the coarse
// meshes CI runs (label validation-ci), 1 the meshes the studies print (validation-full, CTest
// names ending in ".full").
#ifndef PLISSE_VALIDATION_FULL
#define PLISSE_VALIDATION_FULL 0
#endif

namespace plisse::test {

inline constexpr bool kFullTier = PLISSE_VALIDATION_FULL != 0;

/// How a row's difference is formed from the measured value m and the reference r.
enum class Difference {
  relative,  ///< m / r - 1, printed in percent
  absolute,  ///< m - r, in the quantity's unit (exponents, counts, errors against zero)
};

enum class ClaimKind {
  validation,  ///< against theory, experiment or another code, cited in `source`
  regression,  ///< against plisse's own earlier output: a guard, not evidence
};

struct Claim {
  std::string row;       ///< page and row id, e.g. "validation/sheet-tension/wavelength-exponent"
  std::string subject;   ///< the case as the page names it, e.g. "stretched sheet, W/t = 1000"
  std::string quantity;  ///< what is measured, with its unit where it has one
  std::string mesh;      ///< the discretisation the number belongs to
  double measured = 0.0;
  double reference = 0.0;
  std::string source;  ///< the reference: authors, year, equation or figure
  Difference difference = Difference::relative;
  double low = 0.0, high = 0.0;  ///< the claim: low <= difference <= high
  std::string why;               ///< why the band is what it is, in a few words
  ClaimKind kind = ClaimKind::validation;
};

inline double difference_of(const Claim& c) {
  return c.difference == Difference::relative ? c.measured / c.reference - 1.0
                                              : c.measured - c.reference;
}

/// Appends one line to the record named by PLISSE_VALIDATION_RECORD (O_APPEND: CTest's parallel
/// test processes each write whole lines), or does nothing when it is unset or empty.
inline void record_claim(const Claim& c, bool held) {
  const char* path = std::getenv("PLISSE_VALIDATION_RECORD");
  if (!path || !*path) return;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const nlohmann::json line = {
      {"row", c.row},
      {"subject", c.subject},
      {"quantity", c.quantity},
      {"mesh", c.mesh},
      {"measured", c.measured},
      {"reference", c.reference},
      {"source", c.source},
      {"difference_kind", c.difference == Difference::relative ? "relative" : "absolute"},
      {"difference", difference_of(c)},
      {"low", c.low},
      {"high", c.high},
      {"why", c.why},
      {"kind", c.kind == ClaimKind::validation ? "validation" : "regression"},
      {"held", held},
      {"test",
       info ? std::string(info->test_suite_name()) + "." + info->name() + (kFullTier ? ".full" : "")
            : ""}};
  const std::string text = line.dump() + "\n";
  const int fd = ::open(path, O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) {
    ADD_FAILURE() << "cannot append to PLISSE_VALIDATION_RECORD=" << path;
    return;
  }
  const bool written = ::write(fd, text.data(), text.size()) == ssize_t(text.size());
  ::close(fd);
  if (!written) ADD_FAILURE() << "cannot append to PLISSE_VALIDATION_RECORD=" << path;
}

/// Asserts low <= difference <= high (a failure names the row and every number) and records the
/// row. Precondition: low <= high, a reference that is not 0 for a relative difference.
inline void expect_claim(const Claim& c) {
  const double d = difference_of(c);
  const bool held = std::isfinite(d) && d >= c.low && d <= c.high;
  EXPECT_TRUE(held) << c.row << ": " << c.quantity << " measured " << c.measured << " against "
                    << c.reference << " (" << c.source << "): difference " << d
                    << " outside the claim [" << c.low << ", " << c.high << "]";
  record_claim(c, held);
}

}  // namespace plisse::test
