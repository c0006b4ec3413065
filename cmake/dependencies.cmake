# SPDX-License-Identifier: MIT
# Every third-party dependency comes from a Debian package (scripts/install-deps.sh).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(fmt REQUIRED)
find_package(spdlog REQUIRED)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(pugixml 1.11 REQUIRED)

# SuiteSparse (UMFPACK and its ordering libraries) has no CMake config in Debian 12.
find_path(UMFPACK_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(UMFPACK_LIBRARY umfpack REQUIRED)
find_library(AMD_LIBRARY amd REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
add_library(trifem_umfpack INTERFACE)
target_include_directories(trifem_umfpack SYSTEM INTERFACE ${UMFPACK_INCLUDE_DIR})
target_link_libraries(trifem_umfpack INTERFACE ${UMFPACK_LIBRARY} ${AMD_LIBRARY}
                      ${SUITESPARSECONFIG_LIBRARY})

# CHOLMOD (sparse Cholesky of symmetric positive definite systems) and its ordering libraries.
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(COLAMD_LIBRARY colamd REQUIRED)
find_library(CAMD_LIBRARY camd REQUIRED)
find_library(CCOLAMD_LIBRARY ccolamd REQUIRED)
add_library(trifem_cholmod INTERFACE)
target_include_directories(trifem_cholmod SYSTEM INTERFACE ${UMFPACK_INCLUDE_DIR})
target_link_libraries(trifem_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${COLAMD_LIBRARY} ${CAMD_LIBRARY}
                      ${CCOLAMD_LIBRARY} ${AMD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})

# METIS (nested-dissection orderings for the sparse direct solvers): Debian's libmetis-dev.
find_path(METIS_INCLUDE_DIR metis.h REQUIRED)
find_library(METIS_LIBRARY metis REQUIRED)
add_library(trifem_metis INTERFACE)
target_include_directories(trifem_metis SYSTEM INTERFACE ${METIS_INCLUDE_DIR})
target_link_libraries(trifem_metis INTERFACE ${METIS_LIBRARY})

# PETSc (MUMPS, hypre, PT-Scotch, SuperLU_dist) over OpenMPI: Debian's petsc-dev.
find_package(PkgConfig REQUIRED)
pkg_check_modules(PETSC REQUIRED IMPORTED_TARGET PETSc>=3.18)
set(MPI_CXX_SKIP_MPICXX ON) # the C API only, not the deprecated C++ bindings
find_package(MPI REQUIRED COMPONENTS CXX)
add_library(trifem_petsc INTERFACE)
target_link_libraries(trifem_petsc INTERFACE PkgConfig::PETSC MPI::MPI_CXX)

# MUMPS in single precision (preconditioning factorizations), called directly: PETSc's build is
# double precision only. Debian's libmumps-dev, which petsc-dev brings.
find_path(SMUMPS_INCLUDE_DIR smumps_c.h REQUIRED)
find_library(SMUMPS_LIBRARY smumps REQUIRED)
add_library(trifem_smumps INTERFACE)
target_include_directories(trifem_smumps SYSTEM INTERFACE ${SMUMPS_INCLUDE_DIR})
target_link_libraries(trifem_smumps INTERFACE ${SMUMPS_LIBRARY} MPI::MPI_CXX)

if(TRIFEM_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(TRIFEM_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
