// Requirement: the PETSc options of a case or of --petsc are an allow-list of solver options with
// typed values; every option that can make PETSc (or MUMPS, SLEPc) write or read a file, open a
// window or a socket, or start a program is refused before PETSc sees it, however it is spelled.
#include "case/petsc_option_text.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace plisse {
namespace {

/// PETSc 3.18, SLEPc 3.18 and MUMPS options that take a file, a viewer or a program, or change
/// how later options are read, each as a user could give it.
const std::vector<std::string> kFileOptions = {
    // Options files and the option database itself.
    "-options_file /etc/passwd", "-options_file_yaml f.yaml", "-options_string_yaml a",
    "-prefix_push viewer_binary_ -filename /tmp/x -prefix_pop", "-prefix_push ksp_", "-prefix_pop",
    "-filename /tmp/x", "-options_left", "-options_view", "-options_monitor", "-skip_petscrc",
    // Viewer defaults read from the database when a viewer is made.
    "-viewer_binary_filename /tmp/x", "-viewer_binary_skip_info", "-viewer_binary_mpiio",
    "-viewer_ascii_filename /tmp/x", "-viewer_draw_pause 1", "-viewer_socket_port 5000",
    "-viewer_socket_machine host", "-viewer_hdf5_base_dimension2", "-viewer_format ascii_info",
    // Logging, memory and tracing to files.
    "-log_view", "-log_view :timings.txt", "-log_view ascii:/tmp/t.txt", "-log_view_memory",
    "-log_view_gpu_time", "-log_all", "-log_trace", "-log_trace /tmp/trace", "-log_mpe /tmp/mpe",
    "-log_perfstubs", "-log_exclude ksp", "-log_summary", "-history /tmp/h", "-info",
    "-info /tmp/info", "-info :mat", "-malloc_dump", "-malloc_dump /tmp/m", "-malloc_view",
    "-malloc_view /tmp/m", "-malloc_debug", "-memory_view", "-objects_dump", "-stack_view",
    // Debuggers, displays, sockets, programs.
    "-start_in_debugger", "-start_in_debugger gdb", "-on_error_attach_debugger",
    "-stop_for_debugger", "-debugger_ranks 0", "-debugger_pause 5", "-display :0", "-x_virtual",
    "-draw_pause 1", "-saws_port 8080", "-saws_options", "-saws_root /", "-python",
    "-on_error_abort", "-mpi_linear_solver_server", "-help", "-version",
    // Views of objects (binary to binaryoutput, draw, socket, HDF5, VTK, to a file).
    "-ksp_view_mat binary", "-ksp_view_mat", "-ksp_view_pmat binary", "-ksp_view_rhs binary",
    "-ksp_view_solution binary", "-ksp_view_mat_explicit", "-ksp_view_final_residual",
    "-ksp_view_eigenvalues", "-ksp_view_singularvalues",
    "-ksp_view_preconditioned_operator_explicit", "-ksp_view binary", "-ksp_view binary:k.bin",
    "-ksp_view :k.txt", "-ksp_view ascii:/tmp/k.txt", "-ksp_view ::ascii_info:append",
    "-ksp_view draw", "-ksp_view socket", "-ksp_view hdf5:k.h5", "-ksp_view vtk:k.vtk",
    "-ksp_view saws", "-ksp_view glvis", "-ksp_view matlab", "-ksp_view stdout",
    "-snes_view binary", "-snes_view_pre", "-snes_view_solution binary", "-snes_view_update",
    "-snes_test_jacobian_view", "-snes_compare_explicit", "-mat_view binary", "-mat_view",
    "-mat_view ::ascii_matlab", "-vec_view binary", "-pc_view", "-dm_view", "-is_view",
    "-eps_view binary", "-eps_view_values :ev.txt", "-eps_view_vectors binary", "-eps_view_mat0",
    "-eps_view_mat1", "-eps_error_relative :err.txt", "-eps_error_absolute", "-eps_error_backward",
    "-st_view", "-mat_null_space_test_view",
    // Monitors to files, windows or in binary.
    "-ksp_monitor :m.txt", "-ksp_monitor ascii:/tmp/m.txt", "-ksp_monitor binary",
    "-ksp_monitor draw", "-ksp_monitor_solution", "-ksp_monitor_singular_value",
    "-ksp_monitor_lg_residualnorm", "-ksp_monitor_true_residual :m.txt",
    "-ksp_converged_reason :r.txt", "-snes_monitor ascii:log.txt", "-snes_monitor :m.txt",
    "-snes_monitor binary", "-snes_monitor draw::draw_lg", "-snes_monitor_solution",
    "-snes_monitor_residual", "-snes_monitor_solution_update", "-snes_monitor_lg_residualnorm",
    "-snes_monitor_jacupdate_spectrum", "-snes_converged_reason :r.txt",
    "-snes_linesearch_monitor :ls.txt", "-eps_monitor :e.txt", "-eps_monitor_all",
    "-eps_monitor_conv", "-eps_monitor draw::draw_lg",
    // The same behind a solver prefix, and MUMPS's file-writing controls.
    "-fieldsplit_u_ksp_view_mat binary", "-stability_ksp_view binary", "-st_ksp_monitor :m.txt",
    "-fieldsplit_p_ksp_monitor binary", "-mat_mumps_icntl_1 10", "-mat_mumps_icntl_2 11",
    "-mat_mumps_icntl_3 12", "-mat_mumps_icntl_22 1", "-stability_mat_mumps_icntl_1 6",
    "-st_mat_mumps_icntl_22 1",
    // Spellings PETSc reads as the same option.
    "-OPTIONS_FILE /etc/passwd", "--options_file /etc/passwd", "-Ksp_View_Mat binary",
    "-PREFIX_PUSH viewer_binary_", "-KSP_VIEW :k.txt", "-ksp_view BINARY",
    // Quotes, which PETSc reads as one value, and characters PETSc does not split at.
    "-ksp_type \"gmres -options_file /etc/passwd\"", "-ksp_type 'gmres'",
    "-ksp_rtol 1e-8\x01-options_file"};

TEST(PetscOptionText, EveryOptionThatTakesAFileOrAViewerIsRefused) {
  for (const std::string& options : kFileOptions) {
    EXPECT_NE(petsc_option_problem(options), "") << options;
    // After an accepted option too: the check reads every option of the text.
    EXPECT_NE(petsc_option_problem("-ksp_type gmres " + options), "") << options;
  }
}

TEST(PetscOptionText, TheOptionsTheDocsAndTestsUseAreAccepted) {
  for (const std::string& options :
       std::vector<std::string>{"-ksp_type preonly -pc_type lu",
                                "-ksp_view",
                                "-ksp_view ::ascii_info",
                                "-ksp_view ::ascii_info_detail",
                                "-snes_monitor -ksp_view",
                                "-snes_type ksponly",
                                "-snes_lag_jacobian 3 -snes_lag_jacobian_persists",
                                "-snes_lag_jacobian_persists true",
                                "-snes_rtol 1e-10 -snes_atol 1.0e-12 -snes_linesearch_type basic",
                                "-mat_mumps_icntl_14 0",
                                "-mat_mumps_icntl_23 3",
                                "-mat_mumps_icntl_35 2 -mat_mumps_cntl_7 1e-8",
                                "-mat_mumps_icntl_13 1 -mat_mumps_icntl_7 5 -mat_mumps_icntl_28 2",
                                "-stability_mat_mumps_cntl_3 1e-10",
                                "-pc_fieldsplit_schur_fact_type full",
                                "-fieldsplit_u_pc_hypre_boomeramg_strong_threshold 0.7",
                                "-fieldsplit_u_pc_hypre_boomeramg_coarsen_type HMIS",
                                "-fieldsplit_u_pc_hypre_boomeramg_interp_type ext+i",
                                "-fieldsplit_p_ksp_type gmres -fieldsplit_p_pc_type jacobi",
                                "-ksp_monitor_true_residual",
                                "-eps_max_it 2 -eps_monitor -st_pc_factor_mat_solver_type mumps",
                                "--ksp_rtol 1e-6",
                                "-KSP_TYPE gmres",
                                "  -ksp_max_it   50  ",
                                "-ksp_richardson_scale -0.5",
                                ""}) {
    EXPECT_EQ(petsc_option_problem(options), "") << options;
  }
}

TEST(PetscOptionText, AValueOfTheWrongTypeIsRefusedNamingTheOptionAndTheType) {
  EXPECT_EQ(petsc_option_problem("-ksp_rtol small"),
            "'-ksp_rtol small' is refused: the value of -ksp_rtol must be a real number");
  EXPECT_EQ(petsc_option_problem("-ksp_max_it 1.5"),
            "'-ksp_max_it 1.5' is refused: the value of -ksp_max_it must be an integer");
  EXPECT_EQ(petsc_option_problem("-ksp_max_it"),
            "'-ksp_max_it' is refused: its value must be an integer");
  EXPECT_EQ(petsc_option_problem("-pc_jacobi_type row"),
            "'-pc_jacobi_type row' is refused: the value of -pc_jacobi_type must be one of "
            "diagonal, rowmax, rowsum");
  EXPECT_EQ(petsc_option_problem("-snes_lag_jacobian_persists maybe"),
            "'-snes_lag_jacobian_persists maybe' is refused: the value of "
            "-snes_lag_jacobian_persists must be nothing or true/false");
  EXPECT_EQ(petsc_option_problem("-ksp_rtol 1e-8 1e-9"),
            "'1e-9' is neither a PETSc option (options start with '-') nor the value of the "
            "option before it");
  EXPECT_NE(petsc_option_problem("-ksp_rtol nan"), "");
  EXPECT_NE(petsc_option_problem("-ksp_rtol 1e999"), "");
  EXPECT_NE(petsc_option_problem("-mat_mumps_icntl_014 1"), "");
  EXPECT_NE(petsc_option_problem("-mat_mumps_icntl_61 1"), "");
}

TEST(PetscOptionText, AnUnknownOptionIsRefusedNamingIt) {
  EXPECT_EQ(petsc_option_problem("-snes_monitor -ksp_view_mat binary"),
            "'-ksp_view_mat binary' is refused: -ksp_view_mat is not among the solver options "
            "plisse accepts (docs/case-file.md, \"PETSc options\"); every option that names a "
            "file, writes a view or monitor other than text to the log, reads options "
            "(-options_file, -prefix_push) or starts another program is refused");
}

TEST(PetscOptionText, TheDocsTableListsEveryAcceptedOption) {
  const std::string table = petsc_options_markdown();
  EXPECT_NE(table.find("| `-ksp_type` ¹ |"), std::string::npos);
  EXPECT_NE(table.find("| `-mat_mumps_icntl_N` ¹ | integer |"), std::string::npos);
  EXPECT_EQ(table.find("view_mat"), std::string::npos);
}

}  // namespace
}  // namespace plisse
