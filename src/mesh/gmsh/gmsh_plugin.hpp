#pragma once
// The two entry points of the Gmsh plugin (gmsh_mesher.cpp, built as hydrodda_gmsh_mesher.so),
// which gmsh_loader.cpp looks up by name. Only they are visible outside the plugin.

#include <string>

#include "mesh/mesh_request.hpp"

extern "C" {
__attribute__((visibility("default"))) void hydrodda_gmsh_generate_mesh(const hydrodda::mesh::MeshRequest& request,
                                                                        hydrodda::mesh::TriangleMesh& mesh);
__attribute__((visibility("default"))) void hydrodda_gmsh_read_msh(const std::string& path, bool verbose,
                                                                   hydrodda::mesh::TriangleMesh& mesh);
}
