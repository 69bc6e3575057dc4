#include "mesh/gmsh_session.hpp"

#include <gmsh.h>

#include <sstream>

#include "core/error.hpp"

namespace plisse {
namespace {

std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

/// Initialises Gmsh once per process; finalises it when static objects are destroyed at exit.
/// Constructed on first use, hence destroyed before libgmsh's own static state.
struct GmshRuntime {
  GmshRuntime() {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    // Verbosity 2 keeps errors and warnings in the logger (info lines would only cost memory).
    gmsh::option::setNumber("General.Verbosity", 2);
    gmsh::option::setNumber("General.AbortOnError", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
  }
  ~GmshRuntime() {
    try {
      gmsh::finalize();
    } catch (...) {  // nothing sensible can be done at exit
    }
  }
};

void ensure_initialized() { static GmshRuntime runtime; }

std::string join(const std::vector<std::string>& lines) {
  std::ostringstream out;
  for (std::size_t i = 0; i < lines.size(); ++i) out << (i ? "; " : "") << lines[i];
  return out.str();
}

}  // namespace

GmshSession::GmshSession() : lock_(gmsh_mutex()) {
  ensure_initialized();
  gmsh::clear();
  gmsh::logger::stop();
  gmsh::logger::start();
  log_seen_ = 0;
}

GmshSession::~GmshSession() {
  try {
    gmsh::logger::stop();
    gmsh::clear();
  } catch (...) {  // a destructor must not throw; the next session clears again
  }
}

std::vector<std::string> GmshSession::take_errors() {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  std::vector<std::string> errors;
  for (std::size_t i = log_seen_; i < log.size(); ++i) {
    const std::string& line = log[i];
    const std::string prefix = "Error: ";
    if (line.rfind(prefix, 0) == 0) errors.push_back(line.substr(prefix.size()));
  }
  log_seen_ = log.size();
  return errors;
}

void GmshSession::check_input(const std::string& file, const std::string& what) {
  const auto errors = take_errors();
  if (!errors.empty()) throw InputError(InputPlace{file, 0, 0, ""}, what + ": " + join(errors));
}

void GmshSession::check_internal(const std::string& what) {
  const auto errors = take_errors();
  if (!errors.empty()) throw Error(what + ": Gmsh reported: " + join(errors));
}

}  // namespace plisse
