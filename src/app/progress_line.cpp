#include "app/progress_line.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plisse::app {

std::string format_duration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  if (s < 60)
    std::snprintf(text, sizeof text, "%lds", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  return text;
}

LargestWrinkle largest_wrinkle(const WrinkleReport* rings, const std::vector<LineReading>* lines) {
  LargestWrinkle largest;
  double amplitude = -1.0;
  if (rings && rings->wrinkled)
    for (const RingMetrics& ring : rings->rings)
      if (ring.decision == RingDecision::wrinkled && ring.amplitude > amplitude) {
        amplitude = ring.amplitude;
        largest.ring = &ring;
      }
  if (lines)
    for (const LineReading& line : *lines)
      if (line.wrinkled && line.metrics.amplitude > amplitude) {
        amplitude = line.metrics.amplitude;
        largest = {nullptr, &line};
      }
  return largest;
}

std::string progress_line(const StepInfo& info, const WrinkleReport* wrinkles,
                          const ProgressClock& clock, const std::vector<LineReading>* lines) {
  std::string line;
  char part[160];
  std::snprintf(part, sizeof part,
                "step %4d  t %.5g  load %.4f  dt %.3g  newton %2d  reuse %2d  |R| %.3e", info.step,
                info.time, info.load_factor, info.dt, info.newton_iterations, info.reused_solves,
                info.residual_norm);
  line += part;
  if (info.cutbacks > 0) {
    std::snprintf(part, sizeof part, "  cut-backs %d", info.cutbacks);
    line += part;
  }
  // Unstable: more negative pivots than a stable state has; singular: as many, but a null pivot
  // (a critical point, or a direction without stiffness).
  if (info.negative_pivots >= 0 && info.stable) {
    line += "  stable";
  } else if (info.negative_pivots >= 0 && info.negative_pivots != info.expected_negative_pivots) {
    std::snprintf(part, sizeof part, "  UNSTABLE (%d/%d neg. pivots)", info.negative_pivots,
                  info.expected_negative_pivots);
    line += part;
  } else if (info.negative_pivots >= 0) {
    std::snprintf(part, sizeof part, "  SINGULAR (%d zero pivot%s)", info.zero_pivots,
                  info.zero_pivots == 1 ? "" : "s");
    line += part;
  }
  if (const LargestWrinkle largest = largest_wrinkle(wrinkles, lines); largest.ring) {
    std::snprintf(part, sizeof part, "  wrinkled (ring %g deg: %d waves, %.3g mm)",
                  largest.ring->latitude_deg, largest.ring->count, largest.ring->amplitude);
    line += part;
  } else if (largest.line) {
    std::snprintf(part, sizeof part, "  wrinkled (line %.60s: %d crests, %.3g mm)",
                  largest.line->name.c_str(), largest.line->metrics.crests,
                  largest.line->metrics.amplitude);
    line += part;
  } else if (wrinkles && wrinkles->wrinkled) {
    line += "  wrinkled";
  }
  std::snprintf(part, sizeof part, "  elapsed %.1fs", clock.elapsed);
  line += part;
  const double done = info.time - clock.start_time, to_go = clock.end_time - info.time;
  // After cut-backs the rate so far says nothing of the steps to come (a limit load can keep
  // them small for good): no estimate until a step goes through at its first try.
  if (clock.arc_length && info.step > 1 && to_go > 1e-12 * clock.end_time)
    line += "  left unknown (arc length)";
  else if (info.cutbacks > 0 && to_go > 1e-12 * clock.end_time)
    line += "  left unknown (steps cut back)";
  else if (done > 0.0 && to_go > 1e-12 * clock.end_time && clock.stepping > 0.0)
    line += "  left ~" + format_duration(clock.stepping * to_go / done);
  return line;
}

}  // namespace plisse::app
