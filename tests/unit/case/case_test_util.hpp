#pragma once
/// Helpers for the case-file tests: parse text and capture the InputError it must raise.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/case.hpp"
#include "core/error.hpp"

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

/// Item `index` of the case's term section `section` ("loads"); fails the test when there is none.
inline const TermEntry& term(const Case& c, const std::string& section, std::size_t index) {
  const std::vector<const TermEntry*> entries = c.terms_in(section);
  if (index >= entries.size()) {
    ADD_FAILURE() << section << " has " << entries.size() << " items, not " << index + 1;
    static const TermEntry none;
    return none;
  }
  return *entries[index];
}

/// Its settings, as the kind's settings type S.
template <class S>
const S& term_settings(const Case& c, const std::string& section, std::size_t index) {
  return term(c, section, index).as<S>();
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
