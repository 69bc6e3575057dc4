// The `output:` section and its `wrinkles` table.
#include <string>

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

/// `output.wrinkles.lines` items.
Schema<WrinkleLine> wrinkle_line_schema() {
  Schema<WrinkleLine> s;
  s.place(&WrinkleLine::place, false);
  name_key(s, &WrinkleLine::name,
           "names the line's history columns (`wrinkle_crests:<name>`, ...) and its entry in "
           "summary.json")
      .required();
  // `from` and `to`: a point each, with where it is written.
  const auto end_key = [&s](const char* key, Vec3d WrinkleLine::*member,
                            InputPlace WrinkleLine::*place, const char* which) {
    s.add({key,
           "vector",
           "mm",
           "",
           "",
           {},
           std::string(which) +
               " of the line, a point of the undeformed body (of a shell, of its mid-surface)"},
          [member, place](const Field& f, WrinkleLine& line, ReadContext&) {
            line.*member = f.vec3();
            line.*place = f.place();
          })
        .required();
  };
  end_key("from", &WrinkleLine::from, &WrinkleLine::from_place, "one end");
  end_key("to", &WrinkleLine::to, &WrinkleLine::to_place, "the other end");
  s.integer("points", &WrinkleLine::points, Range::closed(16, 20000),
            "points sampled along the line, equally spaced; a wavelength needs about 10 of them");
  s.integer("min_crests", &WrinkleLine::min_crests, Range::at_least(1),
            "fewer crests and troughs along the line are a smooth change of its shape, not "
            "wrinkles (docs/theory/wrinkles.md, W24)");
  s.choice<LineMirror>(
      "mirror", &WrinkleLine::mirror,
      {{"none", LineMirror::none}, {"from", LineMirror::from}, {"to", LineMirror::to}},
      "the end that lies on a mirror plane of the model, which the line crosses at "
      "a right angle: the line is measured with its mirror image beyond that end, "
      "as the whole body has it, so a crest on the plane counts (W21)");
  s.rule("`from` and `to` are different points",
         [](const FieldMap&, const WrinkleLine& line, const ReadContext&) {
           if (line.from == line.to)
             throw InputError(line.to_place, "the line's two ends are the same point " +
                                                 schema::format_vector(line.from) +
                                                 ": give a line of positive length");
         });
  return s;
}

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
         "a ring or line is wrinkled when its amplitude exceeds threshold × wall thickness");
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
  list_key(s, "lines", &WrinkleSettings::lines, wrinkle_line_schema(),
           "measurement lines: straight segments of the undeformed body along which the crests "
           "of wrinkles are counted, with their height and wavelength (docs/theory/wrinkles.md, "
           "W20-W26): a tube's generator, a sheet's width, a film's length");
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
