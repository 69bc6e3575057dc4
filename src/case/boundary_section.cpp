// The `boundary:` section: Dirichlet conditions on tagged surfaces.
#include "case/sections.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/keys.hpp"

namespace plisse::case_detail {
namespace {

const Choices<BoundaryType> kBoundaryTypes{{"fixed", BoundaryType::fixed},
                                           {"symmetry", BoundaryType::symmetry},
                                           {"displacement", BoundaryType::displacement}};

}  // namespace

/// `boundary:` items: Dirichlet conditions on the nodes of a tagged surface.
Schema<BoundaryCondition> boundary_schema() {
  Schema<BoundaryCondition> s;
  s.place(&BoundaryCondition::place, false);
  s.variant<BoundaryType>("type", &BoundaryCondition::type, kBoundaryTypes,
                          "fixed: u = 0; symmetry: zero normal displacement (the surface must be "
                          "planar); displacement: prescribed components")
      .required();
  name_key(s, &BoundaryCondition::name,
           "when given, the reaction force on the surface is reported as `force_x:<name>`, "
           "`force_y:<name>`, `force_z:<name>`");
  surface_key(s, "surface", &BoundaryCondition::surface, "where the condition acts").required();
  s.add({"value",
         "list of 3 numbers or `~`",
         "mm",
         "",
         "",
         {"displacement"},
         "displacement at the end of the ramp; `~` leaves a component free; at least one "
         "component must be given"},
        [](const Field& f, BoundaryCondition& bc, ReadContext&) {
          bc.value = optional_components(f, "displacements [ux, uy, uz] in mm");
          if (!bc.value[0] && !bc.value[1] && !bc.value[2])
            f.fail("at least one component must be prescribed (all three are ~)");
        })
      .required();
  ramp_key(s, &BoundaryCondition::ramp, "time ramp of `value`").applies({"displacement"});
  return s;
}

}  // namespace plisse::case_detail
