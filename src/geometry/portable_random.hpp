#pragma once
// Random numbers that are the same on every machine for a seed. The output of
// std::mt19937_64 is fixed by the C++ standard (its 10,000th value from the default seed is
// specified), but the standard's distributions are not: std::uniform_real_distribution and
// std::normal_distribution leave the algorithm to each library (libstdc++ and libc++ give
// different numbers). So the transforms from the engine's integers are written here.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace hydrodda::geometry {

class PortableRandom {
 public:
  explicit PortableRandom(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1): the top 53 bits of one output times 2⁻⁵³, exact in a double.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  // Standard normal by the Box–Muller transform (Box & Muller 1958), from two uniforms:
  // z = √(−2 ln u1) cos(2π u2) with u1 in (0, 1]. Each call takes exactly two outputs of the
  // engine (the sine's twin is not kept), so a sequence of draws does not depend on which of
  // them were normal. The square root is correctly rounded everywhere; log and cos may differ
  // in the last bit between C libraries, so values agree to round-off across them.
  double normal() {
    const double u1 = 1.0 - uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace hydrodda::geometry
