#pragma once
// The files installed beside the program: the plugins loaded when first needed (Gmsh:
// mesh/gmsh_loader.cpp; the figures' drawing: output/figures_loader.cpp; MPI:
// sweep/mpi/ranks_mpi.cpp) and the flow ordering's helper (numerics/nested_dissection.cpp).

#include <filesystem>
#include <string_view>

namespace hydrodda::base {

// `name` in the running program's folder when it is there, else `built`, where the build
// made it (tests, benchmarks and the Python module run from other folders).
std::filesystem::path find_beside_program(std::string_view name, const std::filesystem::path& built);

}  // namespace hydrodda::base
