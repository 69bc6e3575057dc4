#include "schema/field.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace plisse::schema {
namespace {

std::string lower(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

/// What parsing a number found: a value, not a number, or a number the type cannot hold.
enum class Parsed { ok, not_a_number, out_of_range };

/// YAML 1.2 core-schema floats (".inf", "-.Inf", ".nan", ...) and ordinary decimal numbers,
/// with the whole text consumed. `out_of_range` for a well-formed number beyond the range of a
/// double (1e400, and 1e-400 below the smallest one).
Parsed parse_real(const std::string& text, double& value) {
  std::string s = text;
  const std::string l = lower(s);
  if (l == ".inf" || l == "+.inf")
    return value = std::numeric_limits<double>::infinity(), Parsed::ok;
  if (l == "-.inf") return value = -std::numeric_limits<double>::infinity(), Parsed::ok;
  if (l == ".nan") return value = std::numeric_limits<double>::quiet_NaN(), Parsed::ok;
  if (!s.empty() && s.front() == '+') s.erase(0, 1);
  if (s.empty()) return Parsed::not_a_number;
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value, std::chars_format::general);
  if (ptr != end) return Parsed::not_a_number;
  if (ec == std::errc::result_out_of_range) return Parsed::out_of_range;
  return ec == std::errc() ? Parsed::ok : Parsed::not_a_number;
}

Parsed parse_integer(const std::string& text, long long& value) {
  std::string s = text;
  if (!s.empty() && s.front() == '+') s.erase(0, 1);
  if (s.empty()) return Parsed::not_a_number;
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value);
  if (ptr != end) return Parsed::not_a_number;
  if (ec == std::errc::result_out_of_range) return Parsed::out_of_range;
  return ec == std::errc() ? Parsed::ok : Parsed::not_a_number;
}

/// Optimal-string-alignment distance (insertions, deletions, substitutions, adjacent swaps).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string normalise_for_matching(const std::string& word) {
  std::string s = lower(word);
  std::replace(s.begin(), s.end(), '-', '_');
  return s;
}

}  // namespace

bool Source::from_override(const std::string& path) const {
  for (const std::string& o : override_paths_) {
    if (path == o) return true;
    if (path.size() > o.size() && path.compare(0, o.size(), o) == 0 &&
        (path[o.size()] == '.' || path[o.size()] == '['))
      return true;
  }
  return false;
}

InputPlace Source::place(const YAML::Node& node, const std::string& path) const {
  const YAML::Mark mark = node.Mark();
  if (from_override(path) || mark.is_null()) return {"--set", 0, 0, path};
  return {file_, mark.line + 1, mark.column + 1, path};
}

std::string child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string item_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::optional<std::string> closest_match(const std::string& word,
                                         const std::vector<std::string>& candidates) {
  const std::string w = normalise_for_matching(word);
  // Allowed edits grow with length so that "c3" does not become "c1" but "elment_size" does
  // become "element_size".
  const std::size_t allowed = w.size() <= 2 ? 0 : (w.size() <= 5 ? 1 : (w.size() <= 9 ? 2 : 3));
  std::optional<std::string> best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& c : candidates) {
    // The distance is at least the difference in length: skip the O(n m) table when that alone
    // rules the candidate out (a 10 MB word took 10 s and 1.6 GB per message).
    const std::size_t length_difference =
        w.size() > c.size() ? w.size() - c.size() : c.size() - w.size();
    if (length_difference > allowed) continue;
    const std::size_t d = edit_distance(w, normalise_for_matching(c));
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

std::string format_vector(const Vec3d& v) {
  std::string out = "[";  // appended, not "[" + ...: g++ 12 warns falsely (-Wrestrict) there
  for (int i = 0; i < 3; ++i) out += format_number(v[i]) + (i < 2 ? ", " : "]");
  return out;
}

std::string join(const std::vector<std::string>& words, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) out += (i ? separator : "") + words[i];
  return out;
}

InputPlace Field::place() const {
  if (is_null() && !key_.Mark().is_null()) return source_->place(key_, path_);
  return source_->place(value_, path_);
}

InputPlace Field::key_place() const {
  if (key_.Mark().is_null() && !value_.Mark().is_null()) return source_->place(value_, path_);
  return source_->place(key_, path_);
}

void Field::fail(const std::string& rule) const { throw InputError(place(), rule); }

void Field::fail_at_key(const std::string& rule) const { throw InputError(key_place(), rule); }

std::string Field::describe() const {
  if (is_null()) return "nothing";
  if (value_.IsSequence()) return "a list of " + std::to_string(value_.size()) + " items";
  if (value_.IsMap()) return "a map";
  return quoted_excerpt(value_.Scalar());
}

std::string Field::scalar_for_number(const char* what) const {
  if (!value_.IsScalar()) fail(std::string("expected ") + what + ", got " + describe());
  // yaml-cpp tags quoted scalars "!" (non-specific tag of a non-plain scalar).
  if (value_.Tag() == "!")
    fail(std::string("expected ") + what + ", got the quoted text " + describe() +
         " (write numbers without quotes)");
  return value_.Scalar();
}

double Field::real(const Range& range) const {
  const std::string s = scalar_for_number("a number");
  double v = 0.0;
  const Parsed parsed = parse_real(s, v);
  if (parsed == Parsed::out_of_range)
    fail("the number " + s +
         " is outside the range of double precision (magnitudes from about "
         "2.2e-308 to 1.8e308, or 0)");
  if (parsed != Parsed::ok) fail("expected a number, got " + quoted_excerpt(s));
  if (const auto why = range.violation(v)) fail(*why);
  return v;
}

int Field::integer(const Range& range) const {
  const std::string s = scalar_for_number("an integer");
  long long v = 0;
  const Parsed parsed = parse_integer(s, v);
  if (parsed == Parsed::out_of_range) fail("integer out of range (got " + s + ")");
  if (parsed != Parsed::ok) fail("expected an integer, got " + quoted_excerpt(s));
  if (const auto why = range.violation(static_cast<double>(v))) fail(*why);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    fail("integer out of range (got " + s + ")");
  return static_cast<int>(v);
}

bool Field::boolean() const {
  if (value_.IsScalar() && value_.Tag() != "!") {
    const std::string l = lower(value_.Scalar());
    if (l == "true" || l == "yes" || l == "on") return true;
    if (l == "false" || l == "no" || l == "off") return false;
  }
  fail("expected true or false, got " + describe());
}

std::string Field::text() const {
  if (!value_.IsScalar()) fail("expected a text value, got " + describe());
  return value_.Scalar();
}

std::string Field::name() const {
  const std::string s = text();
  if (s.empty()) fail("a name must not be empty");
  for (char ch : s)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.'))
      fail(
          "a name may contain only letters, digits, '_', '-' and '.' (it becomes an output "
          "column header), got '" +
          s + "'");
  return s;
}

void Field::fail_choice(const std::string& word, const std::vector<std::string>& names) const {
  std::string rule = "must be one of: " + join(names) + " (got " + quoted_excerpt(word) + ")";
  if (const auto guess = closest_match(word, names)) rule += "; did you mean '" + *guess + "'?";
  fail(rule);
}

Vec3d Field::vec3() const {
  if (!value_.IsSequence() || value_.size() != 3)
    fail("expected a list of 3 numbers, e.g. [0, 1, 0], got " + describe());
  const std::vector<double> v = reals();
  return Vec3d(v[0], v[1], v[2]);
}

std::vector<double> Field::reals(const Range& range) const {
  std::vector<double> out;
  if (!is_null() && !value_.IsSequence()) fail("expected a list of numbers, got " + describe());
  for (const Field& item : items()) out.push_back(item.real(range));
  return out;
}

std::vector<Field> Field::items() const {
  std::vector<Field> out;
  if (is_null()) return out;
  if (!value_.IsSequence())
    fail("expected a list (one '- ' item per line, or [a, b]), got " + describe());
  for (std::size_t i = 0; i < value_.size(); ++i)
    out.emplace_back(*source_, value_[i], YAML::Node(), item_path(path_, i));
  return out;
}

FieldMap Field::map() const { return FieldMap(*this); }

FieldMap::FieldMap(const Field& self) : self_(self) {
  const YAML::Node& node = self.node();
  if (self.is_null()) return;
  if (!node.IsMap()) self.fail("expected a map of 'key: value' entries, got " + self.describe());
  // Duplicates are found through a hash map: comparing each key with all earlier ones took
  // minutes for the million keys a 16 MiB case file can hold.
  std::unordered_map<std::string, std::size_t> seen;
  for (auto it = node.begin(); it != node.end(); ++it) {
    const YAML::Node key = it->first;
    if (!key.IsScalar()) {
      Field(self_.source(), it->second, key, self.path()).fail_at_key("expected a plain key");
    }
    const std::string& name = key.Scalar();
    Field field(self_.source(), it->second, key, child_path(self.path(), name));
    if (const auto [first, inserted] = seen.try_emplace(name, entries_.size()); !inserted) {
      const InputPlace p = entries_[first->second].second.key_place();
      field.fail_at_key("key given twice" + (p.line > 0
                                                 ? " (first at line " + std::to_string(p.line) + ")"
                                                 : std::string()));
    }
    entries_.emplace_back(name, std::move(field));
  }
}

std::optional<Field> FieldMap::find(const std::string& key) const {
  for (const auto& [name, field] : entries_)
    if (name == key) return field;
  return std::nullopt;
}

Field FieldMap::require(const std::string& key) const {
  if (auto f = find(key)) return *f;
  InputPlace p = self_.key_place();
  p.key = child_path(self_.path(), key);
  throw InputError(
      p, "required value is missing" + (self_.path().empty()
                                            ? std::string()
                                            : " (add '" + key + ":' to '" + self_.path() + "')"));
}

void FieldMap::check_keys(const std::vector<std::string>& allowed, const std::string& variant,
                          const std::vector<std::string>& other_variants) const {
  for (const auto& [name, field] : entries_) {
    if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
    const std::string list = allowed.empty() ? "none" : join(allowed);
    if (std::find(other_variants.begin(), other_variants.end(), name) != other_variants.end())
      field.fail_at_key("'" + name + "' does not apply to " + variant +
                        "; allowed keys here: " + list);
    std::string rule = "unknown key " + quoted_excerpt(name);
    if (!self_.path().empty()) rule += " in '" + self_.path() + "'";
    if (const auto guess = closest_match(name, allowed))
      rule += " (did you mean '" + *guess + "'?)";
    rule += "; allowed keys" + (variant.empty() ? std::string() : " for " + variant) + ": " + list;
    field.fail_at_key(rule);
  }
}

std::vector<std::string> FieldMap::keys() const {
  std::vector<std::string> out;
  for (const auto& [name, field] : entries_) out.push_back(name);
  return out;
}

double FieldMap::real(const std::string& key, double fallback, const Range& range) const {
  const auto f = find(key);
  return f ? f->real(range) : fallback;
}

int FieldMap::integer(const std::string& key, int fallback, const Range& range) const {
  const auto f = find(key);
  return f ? f->integer(range) : fallback;
}

bool FieldMap::boolean(const std::string& key, bool fallback) const {
  const auto f = find(key);
  return f ? f->boolean() : fallback;
}

}  // namespace plisse::schema
