#pragma once
// A folder of meshes, each stored with the request that made it, so that runs asking for the
// same mesh (a sweep over heads or loads) mesh it once. The key is the request itself, every
// field that shapes the mesh written exactly (canonical_request_text); a file name is a hash of
// it, and a file is used only when the key it holds is the request's, byte for byte, and its
// checksum (FNV-1a of everything before it) matches its contents.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {

// Every field of the request that shapes the mesh, doubles in hexadecimal (exact), one per
// line; `verbose` is left out.
std::string canonical_request_text(const MeshRequest& request);

// The mesh stored at `file` if it was made from `key`; nothing when there is no such file or it
// holds another key. Throws std::runtime_error naming the file when it is cut short, damaged
// (its checksum does not match), of another format or not a valid mesh.
std::optional<TriangleMesh> load_cached_mesh(const std::filesystem::path& file, const std::string& key);
// Writes the mesh and its key to `file` (through a temporary file renamed over it, so that a
// reader never sees half a mesh). Throws std::runtime_error when it cannot.
void save_cached_mesh(const std::filesystem::path& file, const TriangleMesh& mesh, const std::string& key);

struct CachedMesh {
  TriangleMesh mesh;
  bool reused = false;          // read from the folder rather than generated
  bool stored = false;          // generated and stored in the folder
  std::filesystem::path file;   // where it is stored
  // What went wrong with the folder, for the log: an entry discarded, a folder that could not
  // be used or written.
  std::vector<std::string> warnings;
};

// The request's mesh from `folder` (made when missing), else generated with generate_mesh and
// stored there. Runs sharing the folder at the same time mesh each request once: the first
// holds a lock on it (flock on FILE.lock) while it meshes, and the others wait, then read. An
// entry that cannot be used (cut short, damaged, of an older format) is discarded and the mesh
// made again; a folder that cannot be made, locked or written (a full or read-only disk) is
// done without. Either way `warnings` say so, and the mesh is generate_mesh's.
CachedMesh generate_or_reuse_mesh(const MeshRequest& request, const std::filesystem::path& folder);

// Removes the files the cache made in `folder` (its .mesh, .lock and .partial files) and
// nothing else. Throws std::runtime_error when `folder` is not a folder (a symbolic link to
// one is not followed), or a file cannot be removed.
void remove_cache_entries(const std::filesystem::path& folder);

}  // namespace hydrodda::mesh
