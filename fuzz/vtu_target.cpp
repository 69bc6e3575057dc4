// Fuzz target "vtu": the reader of plisse's step files (`plisse wrinkles DIR --step N`, mode
// imperfections from an earlier run), raw or zlib-compressed.
#include "core/error.hpp"
#include "output/vtu_reader.hpp"
#include "scratch_file.hpp"
#include "targets.hpp"

namespace plisse::fuzz {

Outcome read_vtu_file(Bytes data) {
  const auto path = write_scratch_file("step.vtu", data);
  VtuSummary summary;
  std::vector<VtuField> point_fields, cell_fields;
  try {
    summary = read_vtu_summary(path);
    for (const VtuArrayInfo& f : summary.point_fields)
      point_fields.push_back(read_vtu_point_field(path, f.name));
    for (const VtuArrayInfo& f : summary.cell_fields)
      cell_fields.push_back(read_vtu_cell_field(path, f.name));
  } catch (const Error&) {  // InputError derives from Error
    return Outcome::rejected;
  }
  // What the reader accepts holds the values its header declares, for every point or cell.
  const auto check = [](const std::vector<VtuField>& fields, std::uint64_t n_entities) {
    for (const VtuField& f : fields)
      if (f.values.size() != n_entities * static_cast<std::uint64_t>(f.n_components))
        throw Finding("field '" + f.name + "' holds " + std::to_string(f.values.size()) +
                      " values, not its entities times its components");
  };
  check(point_fields, summary.n_points);
  check(cell_fields, summary.n_cells);
  return Outcome::accepted;
}

}  // namespace plisse::fuzz
