# Every dependency is a Debian package installed by scripts/install-deps.sh.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(OpenMP REQUIRED)      # GCC's libgomp: the two-part block factor and sweeps
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(fmt REQUIRED)
find_package(spdlog REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(tomlplusplus REQUIRED)
find_package(ZLIB REQUIRED)          # compressed arrays of the .vtu files (zlib1g-dev)

# SuiteSparse 5 on Debian 12 ships no CMake package: locate CHOLMOD by hand.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
add_library(hydrodda_cholmod INTERFACE)
target_include_directories(hydrodda_cholmod SYSTEM INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(hydrodda_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})
# BLAS and LAPACK (libblas-dev, liblapack-dev; OpenBLAS behind them at run time), called
# directly by the flow's supernodal factorisation on two threads (hydro/supernodal_factorization.cpp).
find_package(LAPACK REQUIRED)
target_link_libraries(hydrodda_cholmod INTERFACE LAPACK::LAPACK)
# METIS (libmetis-dev), called directly for the flow matrix's ordering on two cores
# (hydro/nested_dissection.cpp) as well as by CHOLMOD.
find_path(METIS_INCLUDE_DIR metis.h REQUIRED)
find_library(METIS_LIBRARY metis REQUIRED)
add_library(hydrodda_metis INTERFACE)
target_include_directories(hydrodda_metis SYSTEM INTERFACE ${METIS_INCLUDE_DIR})
target_link_libraries(hydrodda_metis INTERFACE ${METIS_LIBRARY})

# Gmsh's C++ API (libgmsh-dev): a header and a shared library.
find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
add_library(hydrodda_gmsh INTERFACE)
target_include_directories(hydrodda_gmsh SYSTEM INTERFACE ${GMSH_INCLUDE_DIR})
target_link_libraries(hydrodda_gmsh INTERFACE ${GMSH_LIBRARY})

pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)

# jemalloc (libjemalloc-dev), the programs' allocator (src/allocator_options.cpp); the
# sanitizers bring their own.
if(HYDRODDA_SANITIZE OR HYDRODDA_FUZZ)
  set(HYDRODDA_JEMALLOC OFF)
else()
  pkg_check_modules(JEMALLOC REQUIRED IMPORTED_TARGET jemalloc)
  set(HYDRODDA_JEMALLOC ON)
endif()

if(HYDRODDA_BUILD_TESTS)
  find_package(GTest REQUIRED)
  find_package(Boost 1.74 REQUIRED)   # Boost.Geometry, the clipping oracle in tests
endif()
if(HYDRODDA_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()

# Open MPI (libopenmpi-dev), optional: sweeps spread over the ranks of `mpirun hydrodda sweep`
# (src/cli/mpi/). Without it the program is built without MPI and says so in --version.
option(HYDRODDA_MPI "Build MPI sweeps when MPI is found" ON)
if(HYDRODDA_MPI)
  find_package(MPI COMPONENTS C)
endif()
