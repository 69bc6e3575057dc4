# Run-directory writers (owned by the output work): atomic files, VTU/PVD, history.csv,
# summary.json, log.txt, the run directory. Paths relative to src/io.
set(PLISSE_IO_OUTPUT_SOURCES
  append_file.cpp
  atomic_file.cpp
  checkpoint.cpp
  history_writer.cpp
  json_file.cpp
  pvd_writer.cpp
  pvtu_writer.cpp
  run_directory.cpp
  run_log.cpp
  vtu_writer.cpp
)
