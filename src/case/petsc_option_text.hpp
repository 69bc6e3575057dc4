#pragma once
/// PETSc options a case (solver.petsc_options) or the command line (--petsc) may give. The run
/// directory's log is where a run's output goes: an option that names a file (to write, or to
/// read more options from), opens a window or a socket, or starts a debugger is refused before
/// PETSc sees it (PETSc acts on -options_file as soon as the option is inserted).
#include <string>

namespace plisse {

/// Why `options` ("-name [value] -name [value] ...") may not be given, or empty. Refused:
/// - a viewer or monitor value with a file name, or of a type other than ASCII to the terminal
///   (`-ksp_view :out.txt`, `-snes_monitor ascii:log.txt`, `-mat_view binary`, `-ksp_view draw`);
///   format-only values (`-ksp_view ::ascii_info_detail`) are allowed;
/// - options that read or write files by name or start other programs: -options_file,
///   -options_file_yaml, -log_trace, -log_view_memory, -history, -malloc_dump, -malloc_view,
///   -info with a value, the debugger options (-start_in_debugger, -on_error_attach_debugger,
///   -stop_for_debugger, -debugger_*), -display, and any option whose name ends in _file,
///   _filename, _dir or _directory or holds "draw", "_lg_", "socket", "saws" or "glvis".
std::string petsc_option_problem(const std::string& options);

}  // namespace plisse
