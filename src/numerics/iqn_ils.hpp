#pragma once
// The interface quasi-Newton method with an inverse Jacobian from a least-squares model
// (IQN-ILS) for a fixed-point iteration x = G(x): the coupling loop's heads may take it in
// place of Aitken's one relaxation or Anderson's mixing.
//
// A map that is steep in a few directions (a slope of −40 where a wedge sits near its
// threshold) needs a step of 1/41 of a plain pass along them and a whole pass along the rest;
// one ω for all cannot give both. IQN-ILS learns the residual's inverse Jacobian from the
// differences of past passes, so each direction it has seen gets its own step.
//
// Pseudocode (Degroote, Bathe & Vierendeels 2009, Comput. Struct. 87, 793–801, §3; the
// filter "QR2" of Haelterman, Bogaers, Scheufele, Uekermann & Mehl 2016, Comput. Struct. 171):
//   r_k = G(x_k) − x_k
//   V = [r_k − r_{k−1}, r_{k−1} − r_{k−2}, …],  W = [G(x_k) − G(x_{k−1}), …]   newest first
//   filter: Gram–Schmidt V's columns newest first; a column whose part orthogonal to the
//           newer ones kept, |R_ii|, is under ε ‖V_i‖ is dropped from V and W for good
//   c = argmin ‖V c + r_k‖₂  (V = Q R:  R c = −Qᵀ r_k)
//   x_{k+1} = G(x_k) + W c
// With no column (the first pass, or after reset) it is the relaxed step x_k + ω₀ r_k.
// On an affine map it is exact once V holds n independent columns: x_{n+1} is the fixed point.
// The method is Anderson's mixing (anderson.hpp) with the filter and its permanent dropping of
// columns; in exact arithmetic the same iterates from the same columns.

#include <Eigen/Dense>

namespace hydrodda::numerics {

class IqnIls {
 public:
  struct Settings {
    int max_columns = 20;             // the oldest column is dropped past this many
    double filter = 1e-2;             // ε of the QR2 filter
    double initial_relaxation = 1.0;  // ω₀ of a step taken with no column
  };

  explicit IqnIls(Settings settings);
  IqnIls() : IqnIls(Settings{}) {}

  // The next iterate from the current one and its image; both of one size from call to call
  // (a change of size starts again, as reset() does).
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& g);

  // Forget every column: passes of a map that has changed aim at no fixed point of the new one.
  void reset();

  // The columns kept after the last call's filter.
  int columns() const { return static_cast<int>(v_.cols()); }

  // What a checkpoint keeps: the columns and the last pass's residual and image.
  struct History {
    Eigen::MatrixXd v, w;
    Eigen::VectorXd residual, image;
  };
  History history() const { return {v_, w_, residual_, image_}; }
  void restore(History history);

 private:
  void add_columns(const Eigen::VectorXd& residual, const Eigen::VectorXd& image);
  // Q R = V after the filter; V and W lose the columns it drops.
  void filter(Eigen::MatrixXd& q, Eigen::MatrixXd& r);

  Settings settings_;
  Eigen::MatrixXd v_, w_;              // residual and image differences, newest first
  Eigen::VectorXd residual_, image_;   // the last pass's
};

}  // namespace hydrodda::numerics
