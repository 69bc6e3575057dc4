#include "app/shell_fields.hpp"

#include <array>
#include <string>

#include "core/error.hpp"

namespace plisse::app {

std::vector<VtuField> shell_cell_fields(const std::vector<ElementFields>& fields,
                                        const std::vector<shell::ShellOutputs>& outputs) {
  PLISSE_CHECK(fields.size() == outputs.size(),
               "shell cell fields: " << fields.size() << " element fields for " << outputs.size()
                                     << " shell outputs");
  const std::size_t n = outputs.size();
  std::vector<double> pressure(n), thickness(n);
  std::vector<Mat3d> membrane_force(n), bending_moment(n), curvature_change(n);
  std::array<std::vector<Mat3d>, shell::kShellFaces> face_cauchy;
  std::array<std::vector<Vec3d>, shell::kShellFaces> face_stretches;
  for (int f = 0; f < shell::kShellFaces; ++f) {
    face_cauchy[f].resize(n);
    face_stretches[f].resize(n);
  }
  for (std::size_t e = 0; e < n; ++e) {
    const shell::ShellOutputs& s = outputs[e];
    pressure[e] = fields[e].pressure;
    thickness[e] = s.thickness;
    membrane_force[e] = s.membrane_force;
    bending_moment[e] = s.bending_moment;
    curvature_change[e] = s.curvature_change;
    for (int f = 0; f < shell::kShellFaces; ++f) {
      face_cauchy[f][e] = s.face_cauchy[f];
      face_stretches[f][e] = s.face_stretches[f];
    }
  }
  std::vector<VtuField> out = {make_scalar_field("pressure", pressure),
                               make_scalar_field("thickness", thickness),
                               make_symmetric_tensor_field("membrane_force", membrane_force),
                               make_symmetric_tensor_field("bending_moment", bending_moment),
                               make_symmetric_tensor_field("curvature_change", curvature_change)};
  const std::array<const char*, shell::kShellFaces> face_name = {"bottom", "middle", "top"};
  for (int f = 0; f < shell::kShellFaces; ++f)
    out.push_back(
        make_symmetric_tensor_field(std::string("cauchy_stress_") + face_name[f], face_cauchy[f]));
  for (int f = 0; f < shell::kShellFaces; ++f)
    out.push_back(
        make_vector_field(std::string("principal_stretches_") + face_name[f], face_stretches[f]));
  return out;
}

}  // namespace plisse::app
