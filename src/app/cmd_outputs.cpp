/// `plisse outputs [SECTION ...] [--update FILE]`: the output reference (every history.csv column,
/// summary.json key and VTU field, with unit and meaning) as markdown tables; `--update` refreshes
/// the generated blocks of docs/output.md.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/output_reference.hpp"
#include "output/generated_blocks.hpp"

namespace plisse::app {
namespace {

struct OutputsOptions {
  std::vector<std::string> sections;
  std::string update;
};

void print_or_update(const OutputsOptions& o) {
  if (!o.update.empty()) {
    const bool changed = update_generated_blocks(o.update, output_reference_markdown);
    std::cout << o.update << (changed ? ": output tables regenerated\n" : ": up to date\n");
    return;
  }
  std::cout << generated_blocks(o.sections.empty() ? output_reference_sections() : o.sections,
                                output_reference_markdown);
}

}  // namespace

void add_outputs_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("outputs",
                                 "Print the output reference: every history.csv column, "
                                 "summary.json key and VTU field (markdown, as in docs/output.md)");
  auto o = std::make_shared<OutputsOptions>();
  auto* sections = cmd->add_option("sections", o->sections, "Sections to print (default: all)")
                       ->check(CLI::IsMember(output_reference_sections()));
  cmd->add_option("--update", o->update,
                  "Rewrite the generated blocks ('<!-- generated: SECTION -->' ... '<!-- end "
                  "generated -->') of this markdown file, e.g. docs/output.md, instead of printing")
      ->excludes(sections);
  cmd->callback([o] { print_or_update(*o); });
}

}  // namespace plisse::app
