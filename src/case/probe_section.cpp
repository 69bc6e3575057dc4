// The `probes:` section: named material points reported at every step.
#include "case/sections.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/keys.hpp"

namespace plisse::case_detail {

/// `probes:` items: named points reported as displacement columns.
const Choices<ProbeField> kProbeFields{{"displacement", ProbeField::displacement},
                                       {"position", ProbeField::position},
                                       {"pressure", ProbeField::pressure},
                                       {"cauchy", ProbeField::cauchy},
                                       {"von_mises", ProbeField::von_mises},
                                       {"principal_stretches", ProbeField::principal_stretches},
                                       {"principal_stresses", ProbeField::principal_stresses},
                                       {"J", ProbeField::J},
                                       {"thickness", ProbeField::thickness}};

Schema<Probe> probe_schema() {
  Schema<Probe> s;
  s.place(&Probe::place, false);
  name_key(s, &Probe::name, "names the probe's history columns (`ux:<name>`, ...)").required();
  s.add({"point",
         "vector",
         "mm",
         "",
         "",
         {},
         "a material point of the undeformed body: inside it, or on its surface (a point the "
         "mesh's flat facets miss goes to the nearest point of the boundary, and the log and "
         "summary.json give the distance; a point farther from the mesh than the longest edge "
         "of the element there is refused)"},
        [](const Field& f, Probe& probe, ReadContext&) {
          probe.point = f.vec3();
          probe.point_place = f.place();
        })
      .required();
  std::vector<std::string> words;
  for (const auto& [word, field] : kProbeFields) words.push_back(word);
  s.add({"fields",
         "list of " + schema::doc_choice(words),
         "–",
         "",
         "`[displacement]`",
         {},
         "what the probe reports, as history columns (docs/output.md, \"Probes\"): "
         "displacement, position and pressure interpolated at the point, and thickness on a "
         "wall; cauchy, von_mises, principal_stretches, principal_stresses and J are those of "
         "the element holding the point (the step files' cell fields)"},
        [](const Field& f, Probe& probe, ReadContext&) {
          probe.fields_place = f.place();
          if (!f.node().IsSequence() || f.node().size() == 0)
            f.fail("expected a non-empty list of fields, got " + f.describe());
          probe.fields.clear();
          for (const Field& item : f.items()) {
            const ProbeField field = item.choice(kProbeFields);
            if (std::find(probe.fields.begin(), probe.fields.end(), field) != probe.fields.end())
              item.fail("'" + item.text() + "' is listed twice");
            probe.fields.push_back(field);
          }
        });
  return s;
}

}  // namespace plisse::case_detail
