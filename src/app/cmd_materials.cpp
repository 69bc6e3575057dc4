/// `plisse materials [--markdown]`: the registered material models, their formulas and parameters
/// (name, unit, range, default, meaning), straight from the material registry.
#include <iostream>
#include <memory>
#include <sstream>

#include "app/commands.hpp"
#include "material/registry.hpp"

namespace plisse::app {
namespace {

std::string materials_text() {
  std::ostringstream out;
  out << "Material models (isochoric energy W of Ī1, Ī2 or of the isochoric principal stretches;\n"
      << "units MPa). Use in a case file as\n"
      << "  material: {model: NAME, KEY: VALUE, ...}\n";
  for (const auto& m : material_models()) {
    out << '\n'
        << m.name << "\n  " << m.formula << "\n  shear modulus: " << m.shear_modulus << '\n';
    for (const auto& p : m.params) {
      std::ostringstream def;
      if (p.default_value) {
        def << "default " << *p.default_value;
      } else {
        def << "required";
      }
      out << "  " << p.name << " [" << p.unit << "] " << p.range.describe() << ", " << def.str()
          << ": " << p.help << '\n';
    }
    for (const auto& r : m.rules) out << "  rule: " << r.statement << '\n';
  }
  out << "\nAny model, with history (keys of the material section, `plisse case-keys material`):\n"
      << "  viscoelastic: {beta1: B, tau1: T [s], ...}   Prony series, up to three Maxwell "
         "elements;\n"
      << "      the model is the long-term response, the instantaneous one (1 + Σ beta_i) times "
         "it\n"
      << "  mullins: {r: R, m: M [MPa], beta: B}        Ogden-Roxburgh softening below the "
         "largest\n"
      << "      energy reached: the stress scaled by eta in [1 - 1/r, 1]\n";
  return out.str();
}

}  // namespace

void add_materials_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("materials", "List the material models and their parameters");
  auto markdown = std::make_shared<bool>(false);
  cmd->add_flag("--markdown", *markdown, "Print the manual page docs/materials.md instead");
  cmd->callback([markdown] { std::cout << (*markdown ? materials_markdown() : materials_text()); });
}

}  // namespace plisse::app
