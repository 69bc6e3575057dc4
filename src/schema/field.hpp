#pragma once
/// Typed, located reading of a YAML tree: what the case-file parser and the term kinds' key tables
/// read values with.
///
/// A `Field` is one value of the tree together with its key path ("loads[1].value") and where it
/// came from: a line and column of the case file, or a `--set` override (no line). Every typed
/// read checks the YAML type, finiteness and the declared Range, and throws InputError at the
/// value's place with the rule in words. `FieldMap` reads a map: duplicate keys, unknown keys (with
/// the allowed ones and a "did you mean" for typos), required and optional values.
///
/// Ownership: YAML::Node is a shared handle; a Field keeps the tree alive. The Source must outlive
/// every Field made from it.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/parameter.hpp"
#include "core/types.hpp"

namespace plisse::schema {

/// The file name used in messages and the key paths that `--set` replaced (values at or under
/// them are reported as coming from "--set").
class Source {
 public:
  Source(std::string file, std::vector<std::string> override_paths)
      : file_(std::move(file)), override_paths_(std::move(override_paths)) {}
  const std::string& file() const { return file_; }
  /// Place of `node` reached by `path`. Nodes created or replaced by an override (or without a
  /// mark) are placed at "--set" with line 0.
  InputPlace place(const YAML::Node& node, const std::string& path) const;

 private:
  bool from_override(const std::string& path) const;
  std::string file_;
  std::vector<std::string> override_paths_;
};

/// `parent.key` or `key` at the root.
std::string child_path(const std::string& parent, const std::string& key);
/// `parent[index]`.
std::string item_path(const std::string& parent, std::size_t index);

/// The candidate closest to `word` when the difference looks like a typo (at most 1-3 edits
/// depending on length; case and '-' versus '_' ignored), else empty.
std::optional<std::string> closest_match(const std::string& word,
                                         const std::vector<std::string>& candidates);
/// A number as written in messages (up to 12 significant digits), e.g. "0.0033".
std::string format_number(double value);
/// "[x, y, z]" with format_number's digits.
std::string format_vector(const Vec3d& v);
/// "a, b, c".
std::string join(const std::vector<std::string>& words, const std::string& separator = ", ");

class FieldMap;

/// One value of the tree with its key path.
class Field {
 public:
  // yaml-cpp's Node has no move constructor: it is taken by reference and copied once.
  Field(const Source& source, const YAML::Node& value, const YAML::Node& key, std::string path)
      : source_(&source), value_(value), key_(key), path_(std::move(path)) {}

  const std::string& path() const { return path_; }
  const YAML::Node& node() const { return value_; }
  const Source& source() const { return *source_; }
  bool is_null() const { return !value_.IsDefined() || value_.IsNull(); }
  /// Where the value is (the key's place when the value is empty: yaml-cpp marks an empty value
  /// at the start of the next line).
  InputPlace place() const;
  /// Where the key naming this value is (the value's place for list items and the root). A map's
  /// own place: a block map's value is marked at its first entry, not at the line naming it.
  InputPlace key_place() const;
  [[noreturn]] void fail(const std::string& rule) const;
  [[noreturn]] void fail_at_key(const std::string& rule) const;

  /// A finite number within `range`.
  double real(const Range& range = Range::any()) const;
  /// An integer (no fractional part, no exponent) within `range`.
  int integer(const Range& range = Range::any()) const;
  bool boolean() const;
  /// A scalar as written (quoted or not).
  std::string text() const;
  /// A non-empty name usable in output column headers: letters, digits, '_', '-', '.'.
  std::string name() const;
  /// One of `choices` (exact spelling); the error lists them all.
  template <class E>
  E choice(const std::vector<std::pair<std::string, E>>& choices) const {
    const std::string word = text();
    std::vector<std::string> names;
    for (const auto& [name, value] : choices) {
      if (name == word) return value;
      names.push_back(name);
    }
    fail_choice(word, names);
  }
  /// Exactly three finite numbers, e.g. [0, -1, 0].
  Vec3d vec3() const;
  /// A list of finite numbers, each within `range` (empty list allowed).
  std::vector<double> reals(const Range& range = Range::any()) const;
  /// A list (an empty value counts as an empty list).
  std::vector<Field> items() const;
  /// A map (an empty value counts as an empty map); checks for duplicate keys.
  FieldMap map() const;

  /// "a number", "a list", "a map", "nothing", or the scalar quoted.
  std::string describe() const;

 private:
  [[noreturn]] void fail_choice(const std::string& word,
                                const std::vector<std::string>& names) const;
  std::string scalar_for_number(const char* what) const;

  const Source* source_;
  YAML::Node value_;
  YAML::Node key_;
  std::string path_;
};

/// The entries of one YAML map.
class FieldMap {
 public:
  explicit FieldMap(const Field& self);

  const Field& self() const { return self_; }
  bool has(const std::string& key) const { return find(key).has_value(); }
  std::optional<Field> find(const std::string& key) const;
  /// The value at `key`; a missing key is an error at the map's key place naming `path.key`.
  Field require(const std::string& key) const;
  /// Every key must be in `allowed`. A key in `other_variants` (valid for another type/shape/...)
  /// is reported as not applying to `variant`; any other is unknown, with a typo suggestion.
  void check_keys(const std::vector<std::string>& allowed, const std::string& variant = {},
                  const std::vector<std::string>& other_variants = {}) const;
  std::vector<std::string> keys() const;

  double real(const std::string& key, double fallback, const Range& range = Range::any()) const;
  int integer(const std::string& key, int fallback, const Range& range = Range::any()) const;
  bool boolean(const std::string& key, bool fallback) const;
  template <class E>
  E choice(const std::string& key, E fallback,
           const std::vector<std::pair<std::string, E>>& choices) const {
    const auto f = find(key);
    return f ? f->choice(choices) : fallback;
  }

 private:
  Field self_;
  std::vector<std::pair<std::string, Field>> entries_;
};

}  // namespace plisse::schema
