#pragma once
// How the staggered loop mixes each pass's heads with the last ones (coupling.acceleration).

namespace hydrodda::coupling {

// none: the relaxation as given; aitken: the relaxation adapted from pass to pass from the last
// two head updates; anderson: the heads mixed from the last passes (StaggeredLoop::relax).
enum class Acceleration { none, aitken, anderson };

}  // namespace hydrodda::coupling
