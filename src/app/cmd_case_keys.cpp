/// `plisse case-keys [SECTION ...] [--update FILE]`: the key tables of the case-file sections
/// (key, type, unit, default, range, variants, meaning, rules between keys), generated from the
/// case-file schema; `--update` refreshes the generated blocks of the manual docs/case-file.md.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "case/keys.hpp"
#include "core/error.hpp"
#include "output/generated_blocks.hpp"

namespace plisse::app {
namespace {

struct CaseKeysOptions {
  std::vector<std::string> sections;
  std::string update;
};

void print_or_update(const CaseKeysOptions& o) {
  if (!o.update.empty()) {
    const bool changed = update_generated_blocks(o.update, case_keys_markdown);
    std::cout << o.update << (changed ? ": key tables regenerated\n" : ": up to date\n");
    return;
  }
  std::cout << generated_blocks(o.sections.empty() ? case_key_sections() : o.sections,
                                case_keys_markdown);
}

}  // namespace

void add_case_keys_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "case-keys",
      "Print the key tables of the case-file sections (markdown, as in docs/case-file.md)");
  auto o = std::make_shared<CaseKeysOptions>();
  auto* sections = cmd->add_option("sections", o->sections, "Sections to print (default: all)")
                       ->check(CLI::IsMember(case_key_sections()));
  cmd->add_option("--update", o->update,
                  "Rewrite the generated blocks ('<!-- generated: SECTION -->' ... '<!-- end "
                  "generated -->') of this markdown file, e.g. docs/case-file.md, instead of "
                  "printing")
      ->excludes(sections);
  cmd->callback([o] { print_or_update(*o); });
}

}  // namespace plisse::app
