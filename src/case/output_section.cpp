// The `output:` section and its `wrinkles` table.
#include "analysis/wrinkle_rings.hpp"
#include "case/sections.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/keys.hpp"

namespace plisse::case_detail {
namespace {

// A ring at +-90 degrees would be a single point: latitudes are open at the poles.
const Range kLatitude{-90.0, 90.0, true, true};
const Choices<char> kAxes{{"x", 'x'}, {"y", 'y'}, {"z", 'z'}};

}  // namespace

/// `output.wrinkles`.
Schema<WrinkleSettings> wrinkle_schema() {
  Schema<WrinkleSettings> s;
  s.place(&WrinkleSettings::place, true);
  s.choice<char>("axis", &WrinkleSettings::axis, kAxes,
                 "axis of the rings on which wrinkles are measured");
  s.vec3("center", &WrinkleSettings::center, "mm",
         "a point on that axis (the centre of the latitudes)");
  s.add({"rings_deg",
         "list of numbers",
         "deg",
         kLatitude.describe(),
         "empty (no wrinkle metrics)",
         {},
         "latitudes of the rings (0 is the equator; ±90 would be a single point)"},
        [](const Field& f, WrinkleSettings& w, ReadContext&) { w.rings_deg = f.reals(kLatitude); });
  s.real("threshold", &WrinkleSettings::threshold, Range::positive(), "–",
         "a ring is wrinkled when its amplitude exceeds threshold × wall thickness");
  // The rings' spectra reach the full-circle count max_count: a larger min_count leaves nothing
  // to measure.
  s.integer("min_count", &WrinkleSettings::min_count, Range::closed(1, RingSettings{}.max_count),
            "smaller full-circle wave counts (a shift, an ovalisation) are global shape changes, "
            "not wrinkles; at most the largest count the rings' spectra reach");
  s.real("peak_ratio", &WrinkleSettings::peak_ratio, Range::at_least(1.0), "–",
         "a harmonic m ≥ min_count is a wrinkle only if its amplitude exceeds peak_ratio × the "
         "envelope of the global shape there (docs/theory/wrinkles.md, W15–W16); larger is "
         "stricter");
  s.add({"surface",
         "surface tag",
         "–",
         "",
         "`" + WrinkleSettings{}.surface + "`",
         {},
         "the surface the rings are drawn on"},
        [](const Field& f, WrinkleSettings& w, ReadContext&) {
          w.surface = f.text();
          w.surface_place = f.place();
        });
  return s;
}

/// `output:`.
Schema<OutputSettings> output_schema() {
  Schema<OutputSettings> s;
  s.integer("every", &OutputSettings::every, Range::at_least(1),
            "write a VTU file every N converged steps (the last one always; step_0000.vtu, the "
            "undeformed body, first)");
  s.integer("checkpoint_every", &OutputSettings::checkpoint_every, Range::at_least(0),
            "write `checkpoint.bin` every N converged steps (0: only when interrupted); `plisse "
            "run CASE --resume DIR` continues from it");
  s.real("checkpoint_minutes", &OutputSettings::checkpoint_minutes, Range::non_negative(), "min",
         "also write `checkpoint.bin` after a converged step when this much wall time has passed "
         "since the run started or the last checkpoint (0: by step count only), so a long run "
         "loses at most about that much work");
  s.boolean("deformed", &OutputSettings::deformed,
            "write deformed instead of reference coordinates");
  s.choice<VtuCompression>("compression", &OutputSettings::compression,
                           {{"zlib", VtuCompression::zlib}, {"none", VtuCompression::none}},
                           "the step files' data: zlib-compressed (ParaView, VTK and meshio read "
                           "it; about a quarter smaller for a deformed state, ten times for "
                           "step 0) or raw (a little faster to write and read)");
  s.add({"stretch_axis",
         schema::doc_choice({"x", "y", "z"}),
         "–",
         "",
         "none",
         {},
         "adds the history column `stretch` (volume-averaged stretch along that axis)"},
        [](const Field& f, OutputSettings& o, ReadContext&) { o.stretch_axis = f.choice(kAxes); });
  s.nested<WrinkleSettings>("wrinkles", &OutputSettings::wrinkles, wrinkle_schema());
  return s;
}

}  // namespace plisse::case_detail
