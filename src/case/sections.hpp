#pragma once
/// The tables of the case file's sections, one file each (internal to src/case; case.cpp puts them
/// in the top-level table): `mesh` (mesh_section.cpp), `material` (material_section.cpp),
/// `regions`, `probes`, `output` (their *_section.cpp) and `solver` (solver_section.hpp). The term
/// sections (`boundary`, `loads`, `cavities`, `caps`, `dies`, `contacts`) belong to the term kinds
/// of src/terms. Each schema is built anew on each call; the case's table keeps one.
#include <string>

#include "case/case.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/keys.hpp"

namespace plisse::case_detail {

// What every section's file reads and declares its rows with.
using schema::Choices;
using schema::Field;
using schema::FieldMap;
using schema::format_number;
using schema::join;
using schema::KeyDoc;
using schema::ReadContext;
using schema::Schema;
using namespace term_keys;

/// A list of entries, each a map read by `entry`.
template <class S, class E>
typename Schema<S>::Row& list_key(Schema<S>& schema, std::string key,
                                  std::type_identity_t<std::vector<E> S::*> member,
                                  const Schema<E>& entry, std::string help) {
  auto& row = schema.add({std::move(key), "list", "", "", "empty", {}, std::move(help)},
                         [member, entry](const Field& f, S& s, ReadContext& context) {
                           for (const Field& item : f.items()) {
                             E e;
                             entry.read(item, e, context);
                             (s.*member).push_back(std::move(e));
                           }
                         });
  row.nested = entry.doc();
  return row;
}

/// `mesh:`. Its variant is which of `file` and `generate` is given; the generators' options come
/// from the mesh registry (mesh_kinds) and are read by read_mesh.
schema::Schema<MeshSection> mesh_schema();
/// Reads `mesh:` with the options of its generator.
MeshSection read_mesh(const schema::Field& field, schema::ReadContext& context);
/// The table of the generators' options (docs/case-file.md, block "mesh-options").
std::string mesh_options_markdown();

/// `material:`. Its variant is the model; the model's parameters come from the material registry
/// and are read by read_material, which also checks them.
schema::Schema<MaterialSection> material_schema();
/// Reads `material:` (or a region's) with the parameters of its model.
MaterialSection read_material(const schema::Field& field, schema::ReadContext& context);

/// `regions:` items.
schema::Schema<Region> region_schema();
/// `probes:` items.
schema::Schema<Probe> probe_schema();
/// `output:`, with its `wrinkles` table.
schema::Schema<OutputSettings> output_schema();

}  // namespace plisse::case_detail
