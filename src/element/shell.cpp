#include "element/shell.hpp"

#include <variant>

namespace plisse::shell {

ShellStatus assemble_shell(const ShellGeometry& g, const ShellSection& section, const PatchVec& u,
                           const AnyMaterial& material, double inverse_bulk_modulus, PatchVec& r,
                           PatchMat* K) {
  return std::visit(
      [&](const auto& model) {
        return assemble_shell(g, section, u, model, inverse_bulk_modulus, r, K);
      },
      material);
}

double compute_shell_energy(const ShellGeometry& g, const ShellSection& section, const PatchVec& u,
                            const AnyMaterial& material, double inverse_bulk_modulus) {
  return std::visit(
      [&](const auto& model) {
        return compute_shell_energy(g, section, u, model, inverse_bulk_modulus);
      },
      material);
}

}  // namespace plisse::shell
