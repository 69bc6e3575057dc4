#include "element/shell.hpp"

#include <variant>

namespace plisse::shell {

ShellStatus assemble_shell(const ShellGeometry& g, const ShellSection& section, const PatchVec& u,
                           const AnyMaterial& material, PatchVec& r, PatchMat* K) {
  return std::visit([&](const auto& model) { return assemble_shell(g, section, u, model, r, K); },
                    material);
}

double compute_shell_energy(const ShellGeometry& g, const ShellSection& section, const PatchVec& u,
                            const AnyMaterial& material) {
  return std::visit([&](const auto& model) { return compute_shell_energy(g, section, u, model); },
                    material);
}

}  // namespace plisse::shell
