# The case file: schema (case.cpp), located YAML reading (case_reader.cpp), `--set` overrides
# (case_overrides.cpp), checks against the mesh (case_mesh.cpp). Paths relative to src/io.
set(PLISSE_IO_CASE_SOURCES
  case.cpp
  case_reader.cpp
  case_overrides.cpp
  case_mesh.cpp
)
