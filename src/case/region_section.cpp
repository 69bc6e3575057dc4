// The `regions:` section: volume tags, a shell's surface tags, or boxes with a material (and on a
// shell a thickness) of their own, or rigid.
#include "case/sections.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/keys.hpp"

namespace plisse::case_detail {

/// `regions:` items: a volume tag with a material of its own, or rigid.
Schema<Region> region_schema() {
  Schema<Region> s;
  s.place(&Region::place, false);
  s.add({"volume",
         "volume tag",
         "–",
         "",
         "",
         {},
         "the region's tetrahedra (a Gmsh physical volume); a tetrahedron may be in one region "
         "only"},
        [](const Field& f, Region& r, ReadContext&) {
          r.volume = f.name();
          r.volume_place = f.place();
        });
  s.add({"surface",
         "surface tag",
         "–",
         "",
         "",
         {},
         "on a shell: the region's triangles (a Gmsh physical surface of the mesh file); a "
         "triangle may be in one region only"},
        [](const Field& f, Region& r, ReadContext&) {
          r.surface = f.name();
          r.surface_place = f.place();
        });
  s.add({"box",
         "[[x, y, z], [x, y, z]]",
         "mm",
         "lower < upper",
         "",
         {},
         "instead of `volume` or `surface`: the tetrahedra (on a shell, the triangles) whose "
         "centroid lies in this box (lower and upper corners), for generated meshes, which have "
         "no volume tags"},
        [](const Field& f, Region& r, ReadContext&) {
          r.box_place = f.place();
          if (!f.node().IsSequence() || f.node().size() != 2)
            f.fail("expected two corners [[x, y, z], [x, y, z]], got " + f.describe());
          const std::vector<Field> corners = f.items();
          const std::array<Vec3d, 2> box = {corners[0].vec3(), corners[1].vec3()};
          for (int k = 0; k < 3; ++k)
            if (!(box[0][k] < box[1][k]))
              f.fail("the lower corner must be below the upper one in x, y and z (got " +
                     format_number(box[0][k]) + " and " + format_number(box[1][k]) + " in " +
                     std::string(1, "xyz"[k]) + ")");
          r.box = box;
        });
  s.rule("exactly one of `volume`, `surface` and `box`",
         [](const FieldMap& m, const Region& r, const ReadContext&) {
           if (!r.volume.empty() && !r.surface.empty())
             m.require("surface").fail_at_key("give `volume` or `surface`, not both");
           if ((!r.volume.empty() || !r.surface.empty()) && r.box)
             m.require("box").fail_at_key("give a tag (`volume` or `surface`) or `box`, not both");
           if (r.volume.empty() && r.surface.empty() && !r.box)
             m.self().fail_at_key(
                 "give the region's `volume` tag (a solid), `surface` tag (a shell) or its `box`");
         });
  s.add({"material",
         "map",
         "",
         "",
         "none",
         {},
         "the region's model and parameters, with the keys of the case's `material` (model, "
         "parameters, incompressibility, bulk_modulus, density)"},
        [](const Field& f, Region& r, ReadContext& context) {
          // The largest density of the body, for the gravity-load rule.
          const double density = context.density;
          r.material = read_material(f, context);
          context.density = std::max(density, r.material->density);
        });
  s.add({"thickness",
         "number",
         "mm",
         Range::positive().describe(),
         "the mesh's",
         {},
         "on a shell: the region's reference wall thickness (a seam, a patch, a thinner "
         "bladder); each triangle takes its region's, and a node where two thicknesses meet "
         "their mean"},
        [](const Field& f, Region& r, ReadContext&) {
          r.thickness = f.real(Range::positive());
          r.thickness_place = f.place();
        });
  s.boolean("rigid", &Region::rigid,
            "the region moves as a rigid body with the prescribed `displacement`: its elements "
            "are not assembled and its unknowns are eliminated (a stiff support, a die glued to "
            "the membrane)");
  s.add({"displacement",
         "vector",
         "mm",
         "",
         "[0, 0, 0] (held)",
         {},
         "a rigid region's translation at the end of the ramp"},
        [](const Field& f, Region& r, ReadContext&) { r.displacement = f.vec3(); });
  ramp_key(s, &Region::ramp, "time ramp of a rigid region's `displacement`");
  name_key(s, &Region::name,
           "a rigid region's history columns `force_x:<name>` ... (the reaction: the force the "
           "region exerts on the body, N)");
  s.rule("exactly one of `material` and `rigid: true`",
         [](const FieldMap& m, const Region& r, const ReadContext&) {
           if (r.rigid && r.material)
             m.require("material")
                 .fail_at_key("a rigid region has no material: remove `material` or `rigid`");
           if (!r.rigid && !r.material)
             m.self().fail_at_key("give the region a `material`, or make it `rigid: true`");
         });
  s.rule("`thickness` only with `material`",
         [](const FieldMap& m, const Region& r, const ReadContext&) {
           if (r.rigid && r.thickness)
             m.require("thickness").fail_at_key("a rigid region has no wall thickness");
         });
  s.rule("`displacement`, `ramp` and `name` only with `rigid: true`",
         [](const FieldMap& m, const Region& r, const ReadContext&) {
           if (r.rigid) return;
           for (const char* key : {"displacement", "ramp", "name"})
             if (const auto f = m.find(key))
               f->fail_at_key(std::string("`") + key + "` applies only to a rigid region");
         });
  return s;
}

}  // namespace plisse::case_detail
