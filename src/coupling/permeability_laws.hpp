#pragma once
// The permeability laws a scenario may name (flow.permeability_law): each law's name and what it
// needs, in one table that the scenario is read and checked by. What a law computes is its own
// type in permeability_model.cpp, made by the one factory there. A new law is a value of
// PermeabilityLaw with its row here, and its type with its case in that factory.

#include <array>
#include <cstddef>
#include <string_view>

namespace hydrodda::coupling {

enum class PermeabilityLaw { kozeny_carman, cubic };

struct PermeabilityLawInfo {
  PermeabilityLaw law;
  std::string_view name;      // as flow.permeability_law spells it
  bool reads_apertures;       // k from each element's local aperture (local_aperture.hpp)
  bool needs_grain_diameter;  // the material's grain_diameter is required
};

inline constexpr std::array<PermeabilityLawInfo, 2> kPermeabilityLaws{{
    {PermeabilityLaw::kozeny_carman, "kozeny-carman", false, true},
    {PermeabilityLaw::cubic, "cubic", true, false},
}};

// The rows are in the enum's order, so that a law's row is found by its value.
consteval bool rows_in_enum_order() {
  for (std::size_t i = 0; i < kPermeabilityLaws.size(); ++i)
    if (kPermeabilityLaws[i].law != static_cast<PermeabilityLaw>(i)) return false;
  return true;
}
static_assert(rows_in_enum_order(), "kPermeabilityLaws: one row per law, in PermeabilityLaw's order");

constexpr const PermeabilityLawInfo& describe(PermeabilityLaw law) {
  return kPermeabilityLaws[static_cast<std::size_t>(law)];
}

}  // namespace hydrodda::coupling
