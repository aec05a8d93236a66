#pragma once
// METIS keeps one random number generator per process and seeds it afresh at each call: two
// orderings made at once on two threads (two runs in one Python process) draw from each other's
// sequence and come out different from run to run, and so do the heads solved on them, at
// round-off. Gmsh orders with the same METIS while it meshes. Every call into METIS holds this
// lock: the flow matrix's ordering (numerics/nested_dissection.cpp, numerics/cholmod_solver.cpp) and
// every call into Gmsh (gmsh_loader.cpp).

#include <mutex>

namespace hydrodda::base {

std::mutex& metis_lock();

}  // namespace hydrodda::base
