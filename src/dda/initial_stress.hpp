#pragma once
// The in-situ stress as loads at the start of a run (UDEC's insitu): the force a stress field
// puts across a face, shared between its two ends, for the contacts that touch and the
// rollers that hold the blocks from the first step.
//
// A block whose stress is the field's value at its centroid is in equilibrium under these end
// forces when the field is linear and balances the body force (∇·σ + ρ g = 0): the forces sum
// to ∮ σ n ds = ρ g A against gravity, and their first moments Σ (x − x0) ⊗ F to
// ∮ (x − x0) ⊗ σ n ds = A σ(x0), which is what the block's initial-stress load −A σ0 on its
// strain unknowns asks for, because a linear traction's consistent end forces
// L (2 t1 + t2)/6, L (t1 + 2 t2)/6 have the traction's exact first moment along the face.

#include <functional>
#include <span>

#include "dda/definitions.hpp"

namespace hydrodda::dda {

// p's share of the force the field puts across the straight face p–q, on the side whose
// outward unit normal is n: ∫ σ n N_p ds with N_p p's linear weight along the face,
// L (2 σ(p) + σ(q)) n / 6 (exact for a field linear along the face); a face across the knots
// of a layered field is integrated piece by piece, exactly too.
Point compute_face_load(const StressField& field, Point p, Point q, Point n);

// The forces a contact starts with: vertex `vertex` of polygon_i against edge `edge` of
// polygon_j, over the faces incident to the vertex that lie along the edge (those whose length
// the contact carries half of, find_faces_along_edge). Normal: compression positive, pushing
// block i off block j; shear: on block i along the edge's direction.
struct ContactPreload {
  double normal = 0.0;  // N/m
  double shear = 0.0;   // N/m
};
ContactPreload compute_contact_preload(const StressField& field, std::span<const Point> polygon_i, int vertex,
                                       std::span<const Point> polygon_j, int edge, double distance);

// A fluid pressure w's push on block `block`'s face from `from` to `to`, the share of the end
// `from`: ∫ (1 − s/L) w ds, s measured from `from` (N/m).
using FaceShare = std::function<double(int block, Point from, Point to)>;

// The push `share` gives block_i over the same faces as compute_contact_preload, pushing it off
// block j (a pressure pushes each face into its own block): what the contact need not carry.
double compute_contact_fluid_push(const FaceShare& share, int block_i, std::span<const Point> polygon_i, int vertex,
                                  std::span<const Point> polygon_j, int edge, double distance);

}  // namespace hydrodda::dda
