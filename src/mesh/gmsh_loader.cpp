// generate_mesh and read_msh through the Gmsh plugin (mesh/gmsh/gmsh_mesher.cpp), loaded with
// dlopen the first time a mesh is needed, so that a run without a fluid mesh does not load
// Gmsh and OpenCASCADE at its start (see gmsh_mesher.cpp).

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>

#include "mesh/gmsh/gmsh_plugin.hpp"
#include "mesh/mesh_request.hpp"
#include "base/metis_lock.hpp"
#include "base/program_files.hpp"

namespace hydrodda::mesh {
namespace {

namespace fs = std::filesystem;

struct Plugin {
  decltype(&hydrodda_gmsh_generate_mesh) generate = nullptr;
  decltype(&hydrodda_gmsh_read_msh) read = nullptr;
};

// Beside the executable, else where the build made it. Loaded once, never unloaded.
Plugin load_plugin() {
  const base::Plugin library("hydrodda_gmsh_mesher.so", HYDRODDA_GMSH_MESHER, "the Gmsh mesher");
  Plugin plugin;
  plugin.generate = library.entry<decltype(plugin.generate)>("hydrodda_gmsh_generate_mesh");
  plugin.read = library.entry<decltype(plugin.read)>("hydrodda_gmsh_read_msh");
  return plugin;
}

const Plugin& plugin() {
  static const Plugin loaded = load_plugin();
  return loaded;
}

}  // namespace

TriangleMesh generate_mesh(const MeshRequest& request) {
  TriangleMesh mesh;
  const std::lock_guard<std::mutex> one_at_a_time(base::metis_lock());  // Gmsh orders with METIS
  plugin().generate(request, mesh);
  return mesh;
}

TriangleMesh read_msh(const std::string& path, bool verbose) {
  TriangleMesh mesh;
  const std::lock_guard<std::mutex> one_at_a_time(base::metis_lock());
  plugin().read(path, verbose, mesh);
  return mesh;
}

}  // namespace hydrodda::mesh
