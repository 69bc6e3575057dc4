#pragma once
/// Helpers for the case-file tests: parse text and capture the InputError it must raise.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/case.hpp"

namespace plisse::test {

/// Parses `text` (named "case.yaml") and returns the InputError it raises; fails the test if it
/// parses.
inline InputError case_error(const std::string& text,
                             const std::vector<std::string>& overrides = {}) {
  try {
    parse_case_string(text, "case.yaml", overrides);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return InputError({}, "(no error)");
}

/// A minimal valid case; tests append sections to it (lines 1-2).
inline const std::string kMinimalCase =
    "mesh: {generate: cube, edge: 1.0, divisions: 1}\n"
    "material: {model: neo-hookean, c1: 0.1}\n";

}  // namespace plisse::test

/// Asserts the place (file, line, column, key) of an InputError and that its rule contains `part`.
#define EXPECT_INPUT_ERROR(e, file_, line_, column_, key_, part)           \
  do {                                                                     \
    const ::plisse::InputError& err_ = (e);                                \
    EXPECT_EQ(err_.place().file, file_) << err_.what();                    \
    EXPECT_EQ(err_.place().line, line_) << err_.what();                    \
    EXPECT_EQ(err_.place().column, column_) << err_.what();                \
    EXPECT_EQ(err_.place().key, key_) << err_.what();                      \
    EXPECT_NE(err_.rule().find(part), std::string::npos)                   \
        << "rule: " << err_.rule() << "\nexpected to contain: " << (part); \
  } while (false)
