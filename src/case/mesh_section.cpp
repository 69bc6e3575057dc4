// The `mesh:` section: a mesh file or a generator of the mesh registry with its options.
#include <filesystem>

#include "case/sections.hpp"
#include "mesh/generate.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/keys.hpp"

namespace plisse::case_detail {
namespace {

std::vector<std::string> kind_names() {
  std::vector<std::string> out;
  for (const MeshKind& k : mesh_kinds()) out.push_back(k.name);
  return out;
}

}  // namespace

/// `mesh:`. Its variant is which of `file` and `generate` is given; the generators' options come
/// from the mesh registry (mesh_kinds) and are read in read_mesh.
Schema<MeshSection> mesh_schema() {
  Schema<MeshSection> s;
  s.place(&MeshSection::place, true);
  s.add({"file",
         "path",
         "–",
         "",
         "",
         {"file"},
         "a Gmsh `.msh` file (v2 or v4, ASCII or binary); a relative path is read from the "
         "directory of the case file. Physical groups of dimension 2 become surface tags"},
        [](const Field& f, MeshSection& m, ReadContext& context) {
          const std::string text = f.text();
          if (text.empty()) f.fail("the mesh file name must not be empty");
          m.file = schema::resolve_path(text, context.directory);
          m.file_place = f.place();
        });
  s.add({"thickness",
         "number",
         "mm",
         Range::positive().describe(),
         "none",
         {"file"},
         "the wall thickness of a shell read from a file: imperfections, branch switching and "
         "the wrinkle threshold are relative to it"},
        [](const Field& f, MeshSection& m, ReadContext&) {
          m.file_thickness = f.real(Range::positive());
        });
  s.add({"generate",
         schema::doc_choice(kind_names()),
         "–",
         "",
         "",
         {"generate"},
         "generate the mesh; the kind's options (below) may follow"},
        nullptr);
  s.rule("exactly one of `file` and `generate`", nullptr);
  return s;
}

/// The table of the generators' options (docs/case-file.md, block "mesh-options"), from the mesh
/// registry: kind, option, type, unit, range, default (MeshGenerationSpec's), meaning.
std::string mesh_options_markdown() {
  const MeshGenerationSpec defaults;
  std::string md =
      "| kind | option | type | unit | range | default | meaning |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const MeshKind& kind : mesh_kinds()) {
    bool first = true;
    for (const MeshOption& o : kind.options) {
      std::string type = "number", fallback;
      if (o.real) fallback = schema::doc_number(defaults.*o.real);
      if (o.integer) type = "integer", fallback = std::to_string(defaults.*o.integer);
      if (o.symmetry) {
        type = schema::doc_choice(o.symmetries);
        fallback = "`" + to_string(defaults.*o.symmetry) + "`";
      }
      const std::string range = o.symmetry ? "" : Schema<MeshSection>::range_text(o.range);
      std::string help;  // a '|' in the help would end the cell
      for (const char c : o.help) help += c == '|' ? std::string("\\|") : std::string(1, c);
      md += "|" + (first ? " `" + kind.name + "` |" : std::string(" |")) + " `" + o.key + "` | " +
            type + " | " + (o.unit == "-" ? "–" : o.unit) + " |" +
            (range.empty() ? std::string(" |") : " " + range + " |") + " " + fallback + " | " +
            help + " |\n";
      first = false;
    }
  }
  return md;
}

MeshSection read_mesh(const Field& field, ReadContext& context) {
  static const Schema<MeshSection> schema = mesh_schema();
  const FieldMap m = field.map();
  MeshSection s;
  s.place = field.key_place();
  const auto file = m.find("file"), generate = m.find("generate");
  if (file && generate) generate->fail_at_key("give either 'file' or 'generate', not both");
  if (!file && !generate)
    throw InputError(s.place,
                     "needs either 'file: PATH' (a Gmsh .msh file) or 'generate: KIND' "
                     "(one of: " +
                         join(kind_names()) + ")");
  std::vector<std::string> all_options;
  for (const MeshKind& k : mesh_kinds())
    for (const MeshOption& o : k.options) all_options.push_back(o.key);

  if (file) {
    schema.check_keys(m, {"file"}, "a mesh read from a file", {}, all_options);
    schema.read_rows(m, s, context, {"file"});
    return s;
  }

  const std::string kind_name = generate->text();
  const MeshKind* kind = find_mesh_kind(kind_name);
  if (!kind) {
    std::string rule = "unknown mesh kind '" + kind_name + "'; known kinds: " + join(kind_names());
    if (const auto guess = schema::closest_match(kind_name, kind_names()))
      rule += " (did you mean '" + *guess + "'?)";
    generate->fail(rule);
  }
  std::vector<std::string> options;
  for (const MeshOption& o : kind->options) options.push_back(o.key);
  all_options.push_back("file");
  schema.check_keys(m, {"generate"}, "generate: " + kind->name, options, all_options);

  MeshGenerationSpec spec;
  spec.kind = kind->name;
  s.option_places["generate"] = generate->place();
  for (const MeshOption& o : kind->options) {
    const auto f = m.find(o.key);
    if (!f) continue;
    s.option_places[o.key] = f->place();
    if (o.real) {
      spec.*o.real = f->real(o.range);
    } else if (o.integer) {
      spec.*o.integer = f->integer(o.range);
    } else if (o.symmetry) {
      const std::string text = f->text();
      const auto sym = parse_symmetry(text);
      if (!sym) f->fail("must be one of: full, half, quarter, octant (got '" + text + "')");
      spec.*o.symmetry = *sym;
    }
  }
  s.generate = spec;
  return s;
}

}  // namespace plisse::case_detail
