#pragma once
// Where a pass's fluid load holds no block group, the group moved to where its net load
// vanishes (docs/coupling.md, "A group that floats").
//
// A pass holds the fluid load fixed while the DDA steps the blocks. A group of blocks that
// meets nothing in the pass (a column lifted past the critical gradient, rising out of the
// water; a jacked block) has no equilibrium under that load: a static step moves it by
// N Δt²/2M whatever its position (N the net load, M the mass), and the load falls only as the
// next pass's flow sees it elsewhere. The loop x_{k+1} = x_k + N(x_k) Σ Δt²/2M then closes the
// distance to the float by about Σ Δt² K/2M a pass (K = −dN/dx, the fluid's stiffness): a
// tenth at 2,020 steps of 0.01 s for a 10 m column, some hundred passes to converge. The
// secant method on N(x) = 0 takes a handful (superlinear), in the vector form of Barzilai &
// Borwein (IMA J. Numer. Anal. 8 (1988) 141–148, the step length of their eq. 5), which takes
// the stiffness as a scalar:
//
//   per free group g (blocks that met nothing in the pass's last step, joined by their contacts,
//   open or closed: moved as one, no gap among them changes), x its blocks' mean centroid
//   displacement:
//     a_k = (x_end − x_k) / Σ Δt²                   (= N(x_k)/2M: the pass's motion per step²)
//     with the same group free in the pass before, at x_{k−1} with a_{k−1}:
//       s = x_k − x_{k−1},  y = a_k − a_{k−1},  κ = −(y·s)/(s·s)      (K/2M along s)
//       κ Σ Δt² ≥ 10⁻³ (a load that falls as the group moves, the pass closing a thousandth
//       of the distance to the float or more):
//         x* = x_k + a_k/κ  (where the secant's net load vanishes)
//         shift = x* − x_end, scaled down so that
//           – it takes no block back along the group's motion r̂ (r = x_end − x_k) farther than
//             the block advanced along it in the pass (−shift·r̂ ≤ min_b r_b·r̂: each moves
//             only through space it crossed free), and
//           – |shift| ≤ the DDA's allowed step displacement (the contacts a step would find
//             ahead of it are found: the contact search reaches 2.5 times that);
//       κ Σ Δt² < 10⁻³ (κ ≤ 0 above all): no shift (no equilibrium ahead, or one more than a
//              thousand passes' motion away, its κ as likely round-off: the group steps on,
//              and escapes once farther than its size from where it was built: "no equilibrium").
//     remember (x_k, a_k) for the next pass.
//
// A group free in one pass and not the next is forgotten; a group whose blocks change is a new
// group.

#include <map>
#include <span>
#include <vector>

#include "dda/system.hpp"
#include "geometry/point.hpp"

namespace hydrodda::coupling {

using geometry::Point;

// The blocks that met nothing in the last step (landing_steps infinite: dda::FreeDrift),
// grouped by the contacts (open or closed) among them, each group's blocks in ascending order.
std::vector<std::vector<int>> find_free_groups(std::span<const double> landing_steps,
                                               std::span<const dda::ContactInfo> contacts);

class FloatSecant {
 public:
  static constexpr double kLeastClosing = 1e-3;

  // After a pass in which `group` met nothing: its mean centroid displacement at the pass's
  // start and end, the least any of its blocks advanced along the group's motion in the pass
  // (m), the pass's Σ Δt² over its DDA steps, and the largest shift allowed. The shift that
  // takes it to where its net load vanishes ({0, 0}: none), as above.
  Point shift(const std::vector<int>& group, Point start, Point end, double least_advance,
              double sum_squared_steps, double largest_shift);
  // Forgets every group not in `free_now` (free in this pass): the next pass's secant pairs
  // passes in a row only.
  void keep_only(const std::vector<std::vector<int>>& free_now);
  void forget() { last_.clear(); }

  // What it remembers of a group free in the last pass: where the pass started it and its rate
  // a_k, which the next pass pairs with. A checkpoint keeps it, so that a resumed run's next
  // pass takes the secant the run never stopped would.
  struct Remembered {
    std::vector<int> group;  // its blocks, ascending
    Point start;
    Point rate;
  };
  std::vector<Remembered> remembered() const;
  // Takes up what remembered() gave. Throws std::invalid_argument for a group that is empty,
  // not ascending, given twice, or names a block outside [0, block_count).
  void restore(const std::vector<Remembered>& memory, int block_count);

 private:
  struct Memory {
    Point start;
    Point rate;  // a = motion / Σ Δt²
  };
  std::map<std::vector<int>, Memory> last_;
};

}  // namespace hydrodda::coupling
