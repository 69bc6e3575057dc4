#pragma once
/// Runs one of plisse's Python scripts (scripts/*.py, drawn with Debian's python3-matplotlib) with
/// /usr/bin/python3, for the commands that make figures (`plisse plot`, `plisse fit -o`).
#include <string>
#include <vector>

namespace plisse::app {

/// Starts /usr/bin/python3 scripts/<script> args... and waits for it; returns its exit status
/// (-1 if it did not exit normally). Throws Error, naming `command` and the Debian packages it
/// needs, when Python or the script is missing or cannot be started.
int run_python_script(const std::string& command, const std::string& script,
                      const std::vector<std::string>& args);

/// This executable's path (/proc/self/exe), for a script that calls plisse back.
std::string own_executable();

}  // namespace plisse::app
