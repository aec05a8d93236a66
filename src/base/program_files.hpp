#pragma once
// The files installed beside the program: the plugins loaded when first needed (Gmsh:
// mesh/gmsh_loader.cpp; the figures' drawing: output/figures_loader.cpp; MPI:
// sweep/mpi/ranks_mpi.cpp) and the flow ordering's helper (numerics/nested_dissection.cpp).

#include <filesystem>
#include <string>
#include <string_view>

namespace hydrodda::base {

// `name` in the running program's folder when it is there, else `built`, where the build
// made it (tests, benchmarks and the Python module run from other folders).
std::filesystem::path find_beside_program(std::string_view name, const std::filesystem::path& built);

// One of the program's plugins, found as find_beside_program finds it and opened with dlopen;
// never closed (its functions serve to the end of the process). `what` names it in errors
// ("the Gmsh mesher"). `global`: its symbols serve the libraries it opens itself (Open MPI's
// components).
class Plugin {
 public:
  Plugin(std::string_view name, const std::filesystem::path& built, std::string what, bool global = false);

  // The function `symbol` of the plugin, as the pointer type F; an error naming the plugin
  // and the symbol where it lacks it.
  template <class F>
  F entry(const char* symbol) const {
    return reinterpret_cast<F>(address_of(symbol));
  }

 private:
  void* address_of(const char* symbol) const;

  std::filesystem::path path_;
  std::string what_;
  void* handle_ = nullptr;
};

}  // namespace hydrodda::base
