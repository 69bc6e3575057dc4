/// `plisse fit DATA.csv --model NAME [--terms N] [-o DIR]`: fits a material model to uniaxial,
/// equibiaxial and planar test data (docs/fit.md) and prints the parameters, the error per test,
/// the range where the fitted set is stable along each test, and a `material:` block for a case.
/// With -o it also writes material.yaml, fit.json, fit.csv (data and model at every point),
/// curves.csv and fit.png (data against the fitted curves).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/commands.hpp"
#include "app/python_script.hpp"
#include "case/test_data_reader.hpp"
#include "core/error.hpp"
#include "material/material_fit.hpp"
#include "output/append_file.hpp"
#include "output/atomic_file.hpp"
#include "output/json_file.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

struct FitCommandOptions {
  std::string data;
  std::string model;
  int terms = 3;
  std::string output;  ///< folder for the files; none when empty
};

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f %%", 100.0 * fraction);
  return text;
}

std::string range_text(const StabilityRange& s) {
  const bool from_min = s.lower <= kStabilityScanMin, to_max = s.upper >= kStabilityScanMax;
  std::ostringstream out;
  out.precision(3);
  if (from_min && to_max) {
    out << "all of " << kStabilityScanMin << " to " << kStabilityScanMax << " (the range searched)";
  } else {
    out << s.lower << (from_min ? " (end of the search)" : "") << " to " << s.upper
        << (to_max ? " (end of the search)" : "");
  }
  return out.str();
}

/// The text printed to the terminal.
std::string report(const FitCommandOptions& o, const std::vector<TestPoint>& data,
                   const FitResult& fit) {
  std::ostringstream out;
  out << "plisse fit " << o.data << ": " << fit.model;
  if (fit.model == "ogden") out << " (" << o.terms << (o.terms == 1 ? " term)" : " terms)");
  out << ", " << data.size() << " points\n\nparameters (least squares on the relative error of "
      << "the nominal stress):\n";
  const MaterialModelInfo& info = *find_material_model(fit.model);
  for (const ParamSpec& p : info.params) {
    if (std::find(fit.fitted.begin(), fit.fitted.end(), p.name) == fit.fitted.end()) continue;
    char line[128];
    std::snprintf(line, sizeof line, "  %-8s = %-14.6g %s\n", p.name.c_str(), fit.values.at(p.name),
                  p.unit.c_str());
    out << line;
  }
  out << "\nerror per test (relative):\n  test          points  rms        max\n";
  for (const ModeError& e : fit.errors) {
    char line[128];
    std::snprintf(line, sizeof line, "  %-12s  %6d  %-9s  %s\n", test_mode_name(e.mode).c_str(),
                  e.points, percent(e.rms).c_str(), percent(e.max).c_str());
    out << line;
  }
  char all[128];
  std::snprintf(all, sizeof all, "  %-12s  %6zu  %s\n", "all", data.size(),
                percent(fit.rms).c_str());
  out << all;
  out << "\nstable (Drucker: dτ · dε > 0 for every isochoric increment) for stretches:\n";
  for (const StabilityRange& s : fit.stability)
    out << "  " << test_mode_name(s.mode) << ": " << range_text(s) << '\n';
  if (fit.broken.empty()) {
    out << "\nfor a case file:\n" << material_block(fit) << '\n';
  } else {
    out << "\nwarning: the fitted set breaks the rules of model '" << fit.model
        << "', so a case file refuses it:\n";
    for (const ParamViolation& v : fit.broken) out << "  " << v.key << ": " << v.rule << '\n';
    out << "fit fewer terms or another model; the values: " << material_block(fit) << '\n';
  }
  return out.str();
}

void write_files(const FitCommandOptions& o, const std::vector<TestPoint>& data,
                 const FitResult& fit) {
  const fs::path dir = o.output;
  const InputPlace place{dir.string(), 0, 0, "-o"};
  std::error_code ec;
  // Nothing is written through a symbolic link (docs/architecture.md, "Interface contract"):
  // the folder and each file are checked before the first is written.
  if (fs::is_symlink(dir, ec)) throw InputError(place, std::string(kSymbolicLinkRefusal));
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(place, "cannot create the folder: " + ec.message());
  for (const char* name : {"fit.png", "fit.csv", "curves.csv", "material.yaml", "fit.json"})
    if (fs::is_symlink(dir / name, ec))
      throw InputError({(dir / name).string(), 0, 0, "-o"}, std::string(kSymbolicLinkRefusal));
  const AnyMaterial m = make_material_unchecked(fit.model, fit.values);
  std::ostringstream points, curves;
  points.precision(10);
  curves.precision(10);
  points << "mode,stretch,stress,model_stress,relative_error\n";
  for (const TestPoint& p : data) {
    const double t = nominal_stress_or_nan(m, p.mode, p.stretch);
    points << test_mode_name(p.mode) << ',' << p.stretch << ',' << p.stress << ',' << t << ','
           << (t - p.stress) / p.stress << '\n';
  }
  curves << "mode,stretch,model_stress\n";
  for (const ModeError& e : fit.errors) {
    double lo = 1.0, hi = 1.0;
    for (const TestPoint& p : data) {
      if (p.mode != e.mode) continue;
      lo = std::min(lo, p.stretch);
      hi = std::max(hi, p.stretch);
    }
    for (int k = 0; k <= 200; ++k) {
      const double l = lo + (hi - lo) * k / 200.0;
      curves << test_mode_name(e.mode) << ',' << l << ',' << nominal_stress_or_nan(m, e.mode, l)
             << '\n';
    }
  }
  write_file_atomically(dir / "fit.csv", points.str());
  write_file_atomically(dir / "curves.csv", curves.str());
  write_file_atomically(dir / "material.yaml", material_block(fit) + "\n");
  nlohmann::json j;
  j["data"] = o.data;
  j["model"] = fit.model;
  j["units"] = {{"stress", "MPa"}, {"stretch", "-"}};
  for (const auto& [key, value] : fit.values) j["parameters"][key] = value;
  j["fitted"] = fit.fitted;
  j["rms_relative_error"] = fit.rms;
  for (const ModeError& e : fit.errors)
    j["errors"][test_mode_name(e.mode)] = {
        {"points", e.points}, {"rms_relative", e.rms}, {"max_relative", e.max}};
  for (const StabilityRange& s : fit.stability)
    j["stable_stretch_range"][test_mode_name(s.mode)] = {s.lower, s.upper};
  j["broken_rules"] = nlohmann::json::array();
  for (const ParamViolation& v : fit.broken) j["broken_rules"].push_back(v.key + ": " + v.rule);
  j["material_block"] = material_block(fit);
  j["evaluations"] = fit.evaluations;
  write_json_file(dir / "fit.json", j);
  const std::string title = fit.model + " fit to " + fs::path(o.data).filename().string();
  const int status = run_python_script("plisse fit", "plot_fit.py", {dir.string(), title});
  if (status == 2) throw InputError(place, "plot_fit.py refused to write fit.png (see above)");
  if (status != 0) throw Error("plisse fit: drawing fit.png failed (see the messages above)");
}

void fit_command(const FitCommandOptions& o) {
  const std::vector<TestPoint> data = read_test_data(o.data);
  FitSettings options;
  options.model = o.model;
  options.ogden_terms = o.terms;
  const MaterialModelInfo* info = find_material_model(o.model);
  if (info != nullptr) {
    const std::size_t n = fitted_parameters(*info, o.terms).size();
    if (data.size() < n)
      throw InputError({o.data, 0, 0, ""}, std::to_string(data.size()) + " points for " +
                                               std::to_string(n) + " parameters of '" + o.model +
                                               "': the fit needs at least as many points");
  }
  const FitResult fit = fit_material(data, options);
  std::cout << report(o, data, fit) << std::flush;
  if (!o.output.empty()) {
    write_files(o, data, fit);
    std::cout << "written: " << (fs::path(o.output) / "fit.png").string()
              << ", material.yaml, fit.json, fit.csv, curves.csv\n";
  }
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "fit",
      "Fit a material model to uniaxial, equibiaxial and planar test data (nominal stress "
      "against stretch, CSV): parameters, error per test, stability range, a material: block");
  auto o = std::make_shared<FitCommandOptions>();
  cmd->add_option("data", o->data, "CSV file: mode,stretch,stress (MPa), see docs/fit.md")
      ->required();
  cmd->add_option("-m,--model", o->model, "Material model to fit (plisse materials lists them)")
      ->required();
  cmd->add_option("--terms", o->terms, "Number of Ogden terms fitted, 1 to 3 (default 3)");
  cmd->add_option("-o,--output", o->output,
                  "Folder for fit.png, material.yaml, fit.json, fit.csv and curves.csv");
  cmd->callback([o] { fit_command(*o); });
}

}  // namespace plisse::app
