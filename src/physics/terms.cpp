#include "physics/terms.hpp"

#include "physics/body_force.hpp"
#include "physics/cavity.hpp"
#include "physics/die_contact.hpp"
#include "physics/pressure_load.hpp"
#include "physics/viscous_damping.hpp"

namespace plisse {

std::vector<std::unique_ptr<ModelTerm>> make_terms(const Case& c, const Mesh& mesh,
                                                   const std::vector<ConstrainedComponent>& constraints) {
  std::vector<std::unique_ptr<ModelTerm>> terms;
  for (const Load& load : c.loads) {
    switch (load.type) {
      case LoadType::pressure:
        terms.push_back(std::make_unique<PressureLoad>(mesh, load.name, load.surface.name,
                                                       load.value, load.ramp, constraints));
        break;
      case LoadType::gravity:
        terms.push_back(std::make_unique<BodyForce>(
            mesh, load.name, c.material.density * load.acceleration, load.ramp));
        break;
    }
  }
  for (const Cavity& cavity : c.cavities)
    terms.push_back(make_cavity_term(cavity, mesh, constraints));
  for (const Die& die : c.dies) terms.push_back(make_die_term(die, c, mesh, constraints));
  if (c.solver.viscosity > 0.0) {
    // ℓ of docs/theory/viscous.md (V1): the wall thickness (generated shell, airbag or sheet, or
    // `mesh.thickness` of a file mesh), else the mean edge length of the mesh.
    const double length = c.mesh.wall_thickness().value_or(mean_edge_length(mesh));
    terms.push_back(
        std::make_unique<ViscousDamping>(mesh, c.solver.viscosity, length, constraints));
  }
  return terms;
}

}  // namespace plisse
