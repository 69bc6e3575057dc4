#pragma once
/// The declarative schema of one section of a case file: one row per key with
/// its type, unit, range, default, meaning and the variants it applies to, bound to the member of
/// the section's struct it fills. The same rows read the section (unknown keys with "did you mean",
/// keys of another variant, required keys, defaults), check the rules between keys and render the
/// section's table of docs/case-file.md, so a key is spelled once beside its struct member.
///
/// A section is a variant section when some rows are variant keys (`type`, `shape`, ...): those
/// are read first, their values name the variant, and a row with `applies_to` is allowed only when
/// one of its words is among them. Defaults are the struct's own initial values, read from a
/// value-initialised struct; a row made with add() states its default in words ("[0, end_time]").
///
/// Ownership: rows hold std::functions that capture member pointers and, for nested sections,
/// copies of the nested schema; a schema is built once and read concurrently without changes.
#include <algorithm>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/parameter.hpp"
#include "core/types.hpp"
#include "schema/field.hpp"

namespace plisse::schema {

/// What one row of a section's table says (one line of docs/case-file.md).
struct KeyDoc {
  std::string key;            ///< key path inside the section, e.g. "newton.rtol"
  std::string type;           ///< in words, markdown: "number", "`fixed` \| `symmetry`", ...
  std::string unit;           ///< "mm", "MPa", "–" for dimensionless
  std::string range;          ///< admissible values in words, empty when any value of the type is
  std::string default_value;  ///< "required", "1e-8", "`bt`", "none", ...
  std::vector<std::string> applies_to;  ///< variant words; empty: every variant
  std::string help;                     ///< the meaning, one markdown paragraph
};

/// The table of one section: its rows (nested sections flattened with their prefix) and the rules
/// between keys in words.
struct SectionDoc {
  std::vector<KeyDoc> keys;
  std::vector<std::string> rules;
};

/// The markdown table of `doc` (and its rules as a list below it), as in docs/case-file.md. The
/// table has an "applies to" column when some key applies only to some variants.
std::string render_markdown(const SectionDoc& doc);

/// A number as the docs write it: up to 12 significant digits, exponents without padding ("1e-8").
std::string doc_number(double value);

/// `text` as a path relative to the case `directory` (an absolute path is returned unchanged).
std::string resolve_path(const std::string& text, const std::string& directory);

/// "`a` \| `b` \| `c`": a choice between words, in a markdown table cell.
std::string doc_choice(const std::vector<std::string>& words);

/// The choices of an enumeration by input word, in documentation order.
template <class E>
using Choices = std::vector<std::pair<std::string, E>>;

/// What reading a whole case shares between sections: the case directory (relative paths), the
/// default ramp end and the names already used by conditions, loads, cavities, dies and probes.
struct ReadContext {
  std::string directory;
  double end_time = 1.0;  ///< [s], solver.end_time: default end of every ramp
  /// name -> (key path of its entry, place of the name): the five lists share one namespace
  /// because their history columns ("force_x:<name>", "pressure:<name>", ...) must not collide.
  std::map<std::string, std::pair<std::string, InputPlace>> names;
  /// The `density` of the case's material [tonne/mm^3] once read (gravity loads need it).
  double density = 0.0;

  /// `f` as a name not used before by any entry (InputError naming the first user otherwise).
  std::string unique_name(const Field& f);
};

/// The rows of one section whose values go into a struct S.
template <class S>
class Schema {
 public:
  /// Reads a present value into the struct.
  using Read = std::function<void(const Field&, S&, ReadContext&)>;
  /// Runs when the key is absent from an entry it applies to; `map` is the entry.
  using Absent = std::function<void(const FieldMap& map, S&, ReadContext&)>;
  /// A rule between keys, after every row is read; throws InputError with its message.
  using Rule = std::function<void(const FieldMap& map, const S&, const ReadContext&)>;

  struct Row {
    KeyDoc doc;
    Read read;
    Absent absent;             ///< empty: the struct keeps its default
    bool variant = false;      ///< names the variant; read before the keys are checked
    bool null_absent = false;  ///< an empty value (`key:` or `~`) counts as an absent key
    std::function<std::string(const S&)> word;  ///< variant rows: the variant's word
    std::optional<SectionDoc> nested;           ///< nested sections: their rows, unprefixed

    /// The key must be given (an error at the entry otherwise).
    Row& required() {
      doc.default_value = "required";
      absent = [key = doc.key](const FieldMap& m, S&, ReadContext&) { m.require(key); };
      return *this;
    }
    /// Only the listed variants allow the key.
    Row& applies(std::vector<std::string> words) {
      doc.applies_to = std::move(words);
      return *this;
    }
    /// What to do when the key is absent (a default that depends on other sections).
    Row& when_absent(Absent fill) {
      absent = std::move(fill);
      return *this;
    }
    /// An empty value is the same as an absent key.
    Row& null_is_absent() {
      null_absent = true;
      return *this;
    }
  };

  /// A row read by `read` (none: the section's reader reads it): the general form behind the
  /// typed ones below.
  Row& add(KeyDoc doc, Read read) {
    Row& row = rows_.emplace_back();
    row.doc = std::move(doc);
    row.read = std::move(read);
    return row;
  }

  /// A finite number in `range`.
  Row& real(std::string key, double S::*member, Range range, std::string unit, std::string help) {
    Row& row =
        add({std::move(key),
             "number",
             std::move(unit),
             range_text(range),
             doc_number(S{}.*member),
             {},
             std::move(help)},
            [member, range](const Field& f, S& s, ReadContext&) { s.*member = f.real(range); });
    return row;
  }
  /// An integer in `range`.
  Row& integer(std::string key, int S::*member, Range range, std::string help) {
    return add(
        {std::move(key),
         "integer",
         "–",
         range_text(range),
         std::to_string(S{}.*member),
         {},
         std::move(help)},
        [member, range](const Field& f, S& s, ReadContext&) { s.*member = f.integer(range); });
  }
  /// true or false.
  Row& boolean(std::string key, bool S::*member, std::string help) {
    return add(
        {std::move(key), "boolean", "–", "", S{}.*member ? "true" : "false", {}, std::move(help)},
        [member](const Field& f, S& s, ReadContext&) { s.*member = f.boolean(); });
  }
  /// One of `choices`.
  template <class E>
  Row& choice(std::string key, std::type_identity_t<E S::*> member, Choices<E> choices,
              std::string help) {
    std::vector<std::string> words;
    std::string fallback;
    for (const auto& [word, value] : choices) {
      words.push_back(word);
      if (value == S{}.*member) fallback = "`" + word + "`";
    }
    Row& row = add(
        {std::move(key), doc_choice(words), "–", "", fallback, {}, std::move(help)},
        [member, choices](const Field& f, S& s, ReadContext&) { s.*member = f.choice(choices); });
    row.word = [member, choices](const S& s) {
      for (const auto& [word, value] : choices)
        if (value == s.*member) return word;
      return std::string();
    };
    return row;
  }
  /// Like choice(), and the value names the entry's variant.
  template <class E>
  Row& variant(std::string key, std::type_identity_t<E S::*> member, Choices<E> choices,
               std::string help) {
    Row& row = choice<E>(std::move(key), member, std::move(choices), std::move(help));
    row.variant = true;
    return row;
  }
  /// Exactly three finite numbers.
  Row& vec3(std::string key, Vec3d S::*member, std::string unit, std::string help) {
    const Vec3d v = S{}.*member;
    return add({std::move(key),
                "vector",
                std::move(unit),
                "",
                "[" + doc_number(v.x()) + ", " + doc_number(v.y()) + ", " + doc_number(v.z()) + "]",
                {},
                std::move(help)},
               [member](const Field& f, S& s, ReadContext&) { s.*member = f.vec3(); });
  }
  /// A map read by `sub` into the member `member`.
  template <class Sub>
  Row& nested(std::string key, std::type_identity_t<Sub S::*> member, const Schema<Sub>& sub) {
    Row& row = add({std::move(key), "map", "", "", "", {}, ""},
                   [member, sub](const Field& f, S& s, ReadContext& context) {
                     sub.read(f, s.*member, context);
                   });
    row.nested = sub.doc();
    return row;
  }
  /// A map whose keys fill members of S itself (e.g. a die's `move`).
  Row& nested_here(std::string key, const Schema<S>& sub) {
    Row& row = add({std::move(key), "map", "", "", "", {}, ""},
                   [sub](const Field& f, S& s, ReadContext& context) { sub.read(f, s, context); });
    row.nested = sub.doc();
    return row;
  }

  /// A rule between keys, documented by `statement` (markdown) and checked by `check` (none: the
  /// section's reader checks it).
  void rule(std::string statement, Rule check) {
    rules_.emplace_back(std::move(statement), std::move(check));
  }
  /// Where the section is: at its key (`at_key`, for maps) or at its value (list items).
  void place(InputPlace S::*member, bool at_key) {
    place_ = member;
    place_at_key_ = at_key;
  }

  /// Reads the map `field` into `s`: its place, the variant rows, the check of the keys, the
  /// other rows in order, then the rules.
  void read(const Field& field, S& s, ReadContext& context) const {
    const FieldMap m = field.map();
    if (place_) s.*place_ = place_at_key_ ? field.key_place() : field.place();
    std::vector<std::string> active;
    std::string label;
    for (const Row& row : rows_) {
      if (!row.variant) continue;
      read_row(row, m, s, context);
      active.push_back(row.word(s));
      label += (label.empty() ? "" : " with ") + row.doc.key + " '" + active.back() + "'";
    }
    check_keys(m, active, label);
    read_rows(m, s, context, active);
    check_rules(m, s, context);
  }

  /// Reads the map `field` into `s` as the variant `word` of a section whose selector key
  /// (`selector`, e.g. "type") the caller has read and whose other variants have their own
  /// schemas: like read(), with `selector` allowed before the rows, the entry called
  /// "selector 'word'" in messages, and the keys `others` (those of the other variants) named as
  /// not applying to this one.
  void read_selected(const Field& field, S& s, ReadContext& context, const std::string& selector,
                     const std::string& word, const std::vector<std::string>& others) const {
    const FieldMap m = field.map();
    if (place_) s.*place_ = place_at_key_ ? field.key_place() : field.place();
    std::vector<std::string> active;
    std::string label = selector + " '" + word + "'";
    for (const Row& row : rows_) {
      if (!row.variant) continue;
      read_row(row, m, s, context);
      active.push_back(row.word(s));
      label += " with " + row.doc.key + " '" + active.back() + "'";
    }
    std::vector<std::string> allowed = {selector}, other;
    for (const Row& row : rows_) (applies(row, active) ? allowed : other).push_back(row.doc.key);
    for (const std::string& key : others)
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) other.push_back(key);
    m.check_keys(allowed, label, other);
    read_rows(m, s, context, active);
    check_rules(m, s, context);
  }

  /// Checks the keys of `m` against the rows that apply to `active`, plus `extra` (keys read
  /// elsewhere); `others` are keys of other variants read elsewhere.
  void check_keys(const FieldMap& m, const std::vector<std::string>& active,
                  const std::string& label, const std::vector<std::string>& extra = {},
                  const std::vector<std::string>& others = {}) const {
    std::vector<std::string> allowed, other;
    for (const Row& row : rows_) (applies(row, active) ? allowed : other).push_back(row.doc.key);
    allowed.insert(allowed.end(), extra.begin(), extra.end());
    other.insert(other.end(), others.begin(), others.end());
    if (label.empty())
      m.check_keys(allowed);
    else
      m.check_keys(allowed, label, other);
  }
  /// Reads every non-variant row that applies to `active`, in order.
  void read_rows(const FieldMap& m, S& s, ReadContext& context,
                 const std::vector<std::string>& active) const {
    for (const Row& row : rows_)
      if (!row.variant && applies(row, active)) read_row(row, m, s, context);
  }
  /// Reads the row `key` (present: its reader; absent: its absent rule).
  void read_key(const std::string& key, const FieldMap& m, S& s, ReadContext& context) const {
    for (const Row& row : rows_)
      if (row.doc.key == key) return read_row(row, m, s, context);
    throw Error("internal error: no case-schema row '" + key + "'");
  }
  void check_rules(const FieldMap& m, const S& s, const ReadContext& context) const {
    for (const auto& [statement, check] : rules_)
      if (check) check(m, s, context);
  }

  /// The section's keys in order (variant rows included).
  std::vector<std::string> keys() const {
    std::vector<std::string> out;
    for (const Row& row : rows_) out.push_back(row.doc.key);
    return out;
  }
  const std::deque<Row>& rows() const { return rows_; }

  /// The section's table: nested sections flattened as "key.subkey"; a nested row's variants are
  /// named in its range ("`iterative` only"), a nested rule is prefixed "in `key`: ".
  SectionDoc doc() const {
    SectionDoc out;
    for (const Row& row : rows_) {
      if (!row.nested) {
        out.keys.push_back(row.doc);
        continue;
      }
      for (KeyDoc k : row.nested->keys) {
        k.key = row.doc.key + "." + k.key;
        if (!k.applies_to.empty()) {
          std::string only;
          for (const std::string& w : k.applies_to) only += (only.empty() ? "`" : ", `") + w + "`";
          k.range += (k.range.empty() ? "" : "; ") + only + " only";
          k.applies_to.clear();
        }
        k.applies_to = row.doc.applies_to;
        out.keys.push_back(std::move(k));
      }
      for (const std::string& rule : row.nested->rules)
        out.rules.push_back("in `" + row.doc.key + "`: " + rule);
    }
    for (const auto& [statement, check] : rules_) out.rules.push_back(statement);
    return out;
  }

  /// A Range in words for the docs ("> 0", "in (0, 1]"); empty for any finite value.
  static std::string range_text(const Range& range) {
    const std::string text = range.describe();
    return text == Range::any().describe() ? std::string() : text;
  }

 private:
  static bool applies(const Row& row, const std::vector<std::string>& active) {
    if (row.doc.applies_to.empty()) return true;
    for (const std::string& word : row.doc.applies_to)
      for (const std::string& a : active)
        if (word == a) return true;
    return false;
  }
  static void read_row(const Row& row, const FieldMap& m, S& s, ReadContext& context) {
    const auto f = m.find(row.doc.key);
    if (f && !(row.null_absent && f->is_null())) {
      if (row.read) row.read(*f, s, context);
    } else if (row.absent) {
      row.absent(m, s, context);
    }
  }

  std::deque<Row> rows_;
  std::vector<std::pair<std::string, Rule>> rules_;
  InputPlace S::*place_ = nullptr;
  bool place_at_key_ = false;
};

}  // namespace plisse::schema
