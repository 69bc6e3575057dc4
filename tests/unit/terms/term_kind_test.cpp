// The table of term kinds (src/terms): its sections and words, the merged key table of a section
// with a selector, the messages an item gets from its kind, and that every history column a
// kind's term writes is one of the kind's own output rows.
#include "terms/term_kind.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <regex>
#include <set>
#include <string>

#include "case/case.hpp"
#include "mesh/box_mesh.hpp"

namespace plisse {
namespace {

const std::string kCube =
    "mesh: {generate: cube, edge: 2.0, divisions: 2}\n"
    "material: {model: neo-hookean, c1: 0.1, density: 1e-9}\n";

std::string error_of(const std::string& text) {
  try {
    parse_case_string(text, "case.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return "";
}

TEST(TermKinds, EverySectionHasKindsWithDistinctWords) {
  std::set<std::string> sections;
  for (const TermSection& section : term_sections()) {
    sections.insert(section.key);
    const std::vector<const TermKind*> kinds = term_kinds(section.key);
    ASSERT_FALSE(kinds.empty()) << section.key;
    if (section.selector.empty()) {
      EXPECT_EQ(kinds.size(), 1u) << section.key << " has no selector but several kinds";
      continue;
    }
    std::set<std::string> words;
    for (const TermKind* kind : kinds) {
      EXPECT_FALSE(kind->word.empty()) << section.key;
      EXPECT_TRUE(words.insert(kind->word).second)
          << section.key << ": '" << kind->word << "' twice";
    }
  }
  for (const TermKind& kind : term_kinds())
    EXPECT_TRUE(sections.count(kind.section)) << "kind of an unknown section " << kind.section;
  EXPECT_EQ(sections,
            (std::set<std::string>{"boundary", "loads", "cavities", "caps", "dies", "contacts"}));
}

TEST(TermKinds, SelectorRowComesFirstAndRowsSharedByEveryKindApplyToAll) {
  const schema::SectionDoc doc = term_section_doc("loads");
  ASSERT_FALSE(doc.keys.empty());
  EXPECT_EQ(doc.keys[0].key, "type");
  EXPECT_EQ(doc.keys[0].default_value, "required");
  for (const TermKind* kind : term_kinds("loads"))
    EXPECT_NE(doc.keys[0].type.find("`" + kind->word + "`"), std::string::npos) << kind->word;
  const auto row = [&](const std::string& key) {
    std::vector<schema::KeyDoc> out;
    std::copy_if(doc.keys.begin(), doc.keys.end(), std::back_inserter(out),
                 [&](const schema::KeyDoc& k) { return k.key == key; });
    return out;
  };
  // `name` and `ramp` read the same in every kind of load: one row for all of them.
  for (const char* key : {"name", "ramp"}) {
    ASSERT_EQ(row(key).size(), 1u) << key;
    EXPECT_TRUE(row(key)[0].applies_to.empty()) << key;
  }
  // `surface` reads the same in three kinds; `force` means something else in two.
  ASSERT_EQ(row("surface").size(), 1u);
  EXPECT_EQ(row("surface")[0].applies_to,
            (std::vector<std::string>{"pressure", "traction", "follower-traction"}));
  EXPECT_EQ(row("force").size(), 2u);
  // Every kind's rows keep their order in the merged table: `ramp` comes after all others.
  EXPECT_EQ(doc.keys.back().key, "ramp");
}

TEST(TermKinds, ItemsAreJudgedByTheirOwnKind) {
  EXPECT_NE(error_of(kCube + "loads: [{type: presure, name: p, surface: top, value: 1}]\n")
                .find("pressure, gravity, traction, point-force, follower-traction"),
            std::string::npos);
  const std::string other =
      error_of(kCube + "loads: [{type: pressure, name: p, surface: top, value: 1, shear: 1}]\n");
  EXPECT_NE(other.find("'shear' does not apply to type 'pressure'; allowed keys here: type, name, "
                       "surface, value, caps, ramp"),
            std::string::npos)
      << other;
  EXPECT_NE(error_of(kCube + "loads: [{name: p, surface: top, value: 1}]\n")
                .find("key 'loads[0].type': required value is missing"),
            std::string::npos);
}

/// Whether `column` matches the output row `pattern`, whose `<...>` stands for a name.
bool matches(const std::string& pattern, const std::string& column) {
  const std::string re = std::regex_replace(pattern, std::regex("<[^>]*>"), "@");
  std::string escaped;
  for (char ch : re)
    escaped += ch == '@'                                      ? std::string(".+")
               : std::isalnum(static_cast<unsigned char>(ch)) ? std::string(1, ch)
                                                              : std::string("\\") + ch;
  return std::regex_match(column, std::regex(escaped));
}

TEST(TermKinds, EveryColumnATermWritesIsOneOfItsKindsRows) {
  const Case c = parse_case_string(
      kCube +
          "boundary: [{type: fixed, surface: bottom}]\n"
          "loads:\n"
          "  - {type: pressure, name: p, surface: top, value: 1e-3}\n"
          "  - {type: gravity, name: g, acceleration: [0, 0, -9810]}\n"
          "  - {type: traction, name: t, surface: right, traction: [1e-3, 0, 0]}\n"
          "  - {type: point-force, name: f, point: [2, 2, 2], force: [0, 1e-3, 0]}\n"
          "  - {type: follower-traction, name: ft, surface: left, normal: -1e-3}\n"
          "caps: [{name: cap, surface: back}]\n"
          "dies: [{name: die, shape: plane, point: [0, 0, 2.5], normal: [0, 0, -1], surface: top, "
          "contact: "
          "coulomb, friction: 0.2}]\n"
          "contacts: [{name: fold, self: front}]\n",
      "case.yaml");
  const Mesh mesh = load_case_mesh(c);
  const std::vector<ConstrainedComponent> constraints;
  const TermContext context{mesh,
                            constraints,
                            0,
                            [] { return 0.2; },
                            [&] { return std::vector<double>(mesh.tets.size(), 1e-9); },
                            [] { return std::vector<std::array<int, 3>>{}; },
                            [] { return std::vector<CapNodes>{}; }};
  std::set<std::string> made;
  for (const TermEntry& entry : c.terms) {
    if (!entry.kind->make) continue;  // a condition: its columns are the reactions (below)
    const std::unique_ptr<ModelTerm> term = entry.kind->make(entry, context);
    made.insert(entry.kind->section + ":" + entry.kind->word);
    const std::vector<std::string> columns = term->history_columns();
    // A kind declares columns exactly when its term writes some (gravity writes none).
    EXPECT_EQ(columns.empty(), entry.kind->history.empty()) << entry.name;
    for (const std::string& column : columns)
      EXPECT_TRUE(std::any_of(entry.kind->history.begin(), entry.kind->history.end(),
                              [&](const OutputEntry& e) { return matches(e.name, column); }))
          << entry.kind->section << " " << entry.kind->word << " writes '" << column
          << "', which none of its output rows names";
  }
  // Every kind of term but the cavity (its wall must enclose a volume; tests/unit/cavity builds
  // it).
  const auto terms = std::count_if(term_kinds().begin(), term_kinds().end(),
                                   [](const TermKind& kind) { return bool(kind.make); });
  EXPECT_EQ(made.size(), static_cast<std::size_t>(terms - 1));
  // A condition makes no term: it constrains, and its reaction is what the history reports.
  for (const TermKind* kind : term_kinds("boundary")) {
    EXPECT_FALSE(kind->make) << kind->word;
    EXPECT_TRUE(kind->constrain && kind->surface) << kind->word;
    EXPECT_TRUE(std::any_of(kind->history.begin(), kind->history.end(), [](const OutputEntry& e) {
      return e.name == "force_x:<boundary>";
    })) << kind->word;
  }
}

// The conditions of a cube of edge 2: fixed bottom (z = 0), symmetry on the left (x = 0), and
// the top (z = 2) moved 0.5 up. The held components, counted from the nodes' coordinates: every
// component at z = 0, x at x = 0, z at z = 2; where two conditions hold the same component with
// zero motion they agree.
TEST(TermKinds, ConditionsHoldTheirSurfacesComponentsAndJudgeConflicts) {
  const std::string conditions =
      "boundary:\n"
      "  - {type: fixed, surface: bottom}\n"
      "  - {type: symmetry, surface: left}\n"
      "  - {type: displacement, surface: top, value: [~, ~, 0.5]}\n";
  const Case c = parse_case_string(kCube + conditions, "case.yaml");
  const Mesh mesh = load_case_mesh(c);
  std::set<std::pair<int, int>> expected;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d& x = mesh.nodes[v];
    if (x.z() == 0.0) expected.insert({{v, 0}, {v, 1}, {v, 2}});
    if (x.x() == 0.0) expected.insert({v, 0});
    if (x.z() == 2.0) expected.insert({v, 2});
  }
  std::set<std::pair<int, int>> held;
  for (const ConstrainedComponent& cc : collect_constraints(c.terms, mesh)) {
    EXPECT_TRUE(held.insert({cc.node, cc.component}).second) << "held twice: " << cc.node;
    const double top = mesh.nodes[cc.node].z() == 2.0 && cc.component == 2 ? 0.5 : 0.0;
    EXPECT_EQ(cc.value, top) << cc.node << " " << cc.component;
  }
  EXPECT_EQ(held, expected);
  EXPECT_EQ(mirror_surfaces(c.terms), std::vector<std::string>{"left"});
  // Moving the bottom, which the first condition fixes, is refused at the later condition.
  const Case conflict = parse_case_string(
      kCube + conditions + "  - {type: displacement, surface: bottom, value: [0.1, ~, ~]}\n",
      "case.yaml");
  try {
    collect_constraints(conflict.terms, mesh);
    ADD_FAILURE() << "a conflict between two conditions was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().key, "boundary[3]");
    EXPECT_NE(std::string(e.what()).find("x displacement prescribed differently by the "
                                         "condition on 'bottom'"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace plisse
