# The case file: schema tables and section readers (case.cpp; the solver section's tables in
# case_solver_schema.cpp), the schema machinery and its
# markdown (case_schema.cpp), the generated tables of docs/case-file.md (case_keys.cpp), the raw
# YAML text (yaml_text.cpp), located YAML reading (case_reader.cpp), `--set` overrides
# (case_overrides.cpp), checks against the mesh (case_mesh.cpp). Paths relative to src/io.
set(PLISSE_IO_CASE_SOURCES
  case.cpp
  case_schema.cpp
  case_solver_schema.cpp
  petsc_option_text.cpp
  case_keys.cpp
  generated_blocks.cpp
  yaml_text.cpp
  case_reader.cpp
  case_overrides.cpp
  case_mesh.cpp
)
