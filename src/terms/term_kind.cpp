// Reading and documenting a term section from its kinds: the selector key picks the kind, whose
// own schema reads the rest; the section's table merges the kinds' rows.
#include "terms/term_kind.hpp"

#include <algorithm>

namespace plisse {
namespace {

using schema::KeyDoc;
using schema::SectionDoc;

bool same_row(const KeyDoc& a, const KeyDoc& b) {
  return a.key == b.key && a.type == b.type && a.unit == b.unit && a.range == b.range &&
         a.default_value == b.default_value && a.help == b.help;
}

/// Adds `row` (of the kind `word`) to `rows`: to the same row of an earlier kind, or as a new row
/// placed before the first row already there that follows it in its own kind (`later`), so that
/// every kind's rows keep their order.
void merge_row(std::vector<KeyDoc>& rows, KeyDoc row, const std::string& word,
               const std::vector<std::string>& later) {
  for (KeyDoc& existing : rows)
    if (same_row(existing, row)) {
      existing.applies_to.push_back(word);
      return;
    }
  row.applies_to = {word};
  auto at = rows.end();
  for (const std::string& key : later) {
    at = std::find_if(rows.begin(), rows.end(), [&](const KeyDoc& k) { return k.key == key; });
    if (at != rows.end()) break;
  }
  rows.insert(at, std::move(row));
}

}  // namespace

const TermSection& term_section(const std::string& key) {
  for (const TermSection& s : term_sections())
    if (s.key == key) return s;
  throw Error("internal error: no term section '" + key + "'");
}

std::vector<const TermEntry*> entries_in(const std::vector<TermEntry>& entries,
                                         const std::string& section) {
  std::vector<const TermEntry*> out;
  for (const TermEntry& entry : entries)
    if (entry.kind->section == section) out.push_back(&entry);
  return out;
}

std::vector<const TermKind*> term_kinds(const std::string& section) {
  std::vector<const TermKind*> out;
  for (const TermKind& kind : term_kinds())
    if (kind.section == section) out.push_back(&kind);
  return out;
}

std::vector<ConstrainedComponent> collect_constraints(const std::vector<TermEntry>& entries,
                                                      const Mesh& mesh) {
  ConstraintSet set;
  for (const TermEntry& entry : entries) {
    if (!entry.kind->constrain) continue;
    set.begin(entry.place, entry.kind->surface(entry).name);
    entry.kind->constrain(entry, mesh, set);
  }
  return set.components();
}

std::vector<std::string> mirror_surfaces(const std::vector<TermEntry>& entries) {
  std::vector<std::string> out;
  for (const TermEntry& entry : entries)
    if (entry.kind->mirror) out.push_back(entry.kind->surface(entry).name);
  return out;
}

TermEntry read_term(const std::string& section, const schema::Field& item,
                    schema::ReadContext& context) {
  const TermSection& s = term_section(section);
  const std::vector<const TermKind*> kinds = term_kinds(section);
  if (s.selector.empty()) {
    TermEntry entry = kinds.front()->read(item, context, "", {});
    entry.kind = kinds.front();
    return entry;
  }
  const schema::FieldMap m = item.map();
  schema::Choices<const TermKind*> choices;
  for (const TermKind* kind : kinds) choices.emplace_back(kind->word, kind);
  const auto selector = m.find(s.selector);
  if (!selector) m.require(s.selector);
  const TermKind* kind = selector->choice(choices);
  std::vector<std::string> others;
  for (const TermKind* other : kinds)
    if (other != kind)
      for (const KeyDoc& key : other->doc().keys) others.push_back(key.key);
  TermEntry entry = kind->read(item, context, s.selector, others);
  entry.kind = kind;
  return entry;
}

SectionDoc term_section_doc(const std::string& section) {
  const TermSection& s = term_section(section);
  const std::vector<const TermKind*> kinds = term_kinds(section);
  if (s.selector.empty()) return kinds.front()->doc();
  std::vector<std::string> words, meanings;
  for (const TermKind* kind : kinds) {
    words.push_back(kind->word);
    meanings.push_back(kind->word + ": " + kind->summary);
  }
  SectionDoc out;
  out.keys.push_back({s.selector,
                      schema::doc_choice(words),
                      "–",
                      "",
                      "required",
                      {},
                      schema::join(meanings, "; ")});
  for (const TermKind* kind : kinds) {
    const SectionDoc doc = kind->doc();
    for (std::size_t k = 0; k < doc.keys.size(); ++k) {
      std::vector<std::string> later;
      for (std::size_t j = k + 1; j < doc.keys.size(); ++j) later.push_back(doc.keys[j].key);
      merge_row(out.keys, doc.keys[k], kind->word, later);
    }
    for (const std::string& rule : doc.rules)
      if (std::find(out.rules.begin(), out.rules.end(), rule) == out.rules.end())
        out.rules.push_back(rule);
  }
  for (KeyDoc& row : out.keys)
    if (row.applies_to.size() == kinds.size()) row.applies_to.clear();
  return out;
}

}  // namespace plisse
