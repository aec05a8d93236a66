#pragma once
// How a scenario file spells the engines' choices: one table per enum, which the reader reads a
// value through and which every message, log line and summary that names a value writes it
// from. The scenario holds the engines' own enums; a permeability law's name is the law's
// (coupling/permeability_laws.hpp), and its table here is made from it.

#include <array>
#include <cstddef>
#include <string_view>

#include "coupling/load_ramp.hpp"
#include "coupling/loop_acceleration.hpp"
#include "coupling/permeability_laws.hpp"
#include "dda/definitions.hpp"
#include "geometry/tessellation.hpp"
#include "hydro/boundary_condition.hpp"
#include "hydro/permeability_law.hpp"

namespace hydrodda::scenario {

template <typename Enum>
struct Spelling {
  Enum value;
  std::string_view text;
};

// Spellings<Enum>::table: every value of Enum once, with its text in the scenario file.
template <typename Enum>
struct Spellings;

template <>
struct Spellings<dda::Analysis> {  // mechanics.analysis
  static constexpr std::array<Spelling<dda::Analysis>, 2> table{{
      {dda::Analysis::static_, "static"},
      {dda::Analysis::dynamic, "dynamic"},
  }};
};

template <>
struct Spellings<dda::Plane> {  // mechanics.plane
  static constexpr std::array<Spelling<dda::Plane>, 2> table{{
      {dda::Plane::strain, "strain"},
      {dda::Plane::stress, "stress"},
  }};
};

template <>
struct Spellings<dda::ContactMethod> {  // mechanics.contact
  static constexpr std::array<Spelling<dda::ContactMethod>, 2> table{{
      {dda::ContactMethod::augmented_lagrangian, "augmented-lagrangian"},
      {dda::ContactMethod::penalty, "penalty"},
  }};
};

template <>
struct Spellings<geometry::TessellationKind> {  // geometry.tessellate.kind
  static constexpr std::array<Spelling<geometry::TessellationKind>, 2> table{{
      {geometry::TessellationKind::voronoi, "voronoi"},
      {geometry::TessellationKind::triangles, "triangles"},
  }};
};

template <>
struct Spellings<hydro::PressureConvention> {  // flow.pressure
  static constexpr std::array<Spelling<hydro::PressureConvention>, 2> table{{
      {hydro::PressureConvention::overpressure, "overpressure"},
      {hydro::PressureConvention::hydrostatic, "hydrostatic"},
  }};
};

template <>
struct Spellings<hydro::BoundaryKind> {  // the key a [[flow.boundary]] gives its value under
  static constexpr std::array<Spelling<hydro::BoundaryKind>, 3> table{{
      {hydro::BoundaryKind::head, "head"},
      {hydro::BoundaryKind::pressure, "pressure"},
      {hydro::BoundaryKind::flux, "flux"},
  }};
};

template <>
struct Spellings<coupling::Acceleration> {  // coupling.acceleration
  static constexpr std::array<Spelling<coupling::Acceleration>, 3> table{{
      {coupling::Acceleration::none, "none"},
      {coupling::Acceleration::aitken, "aitken"},
      {coupling::Acceleration::anderson, "anderson"},
  }};
};

template <>
struct Spellings<hydro::HydraulicOpening> {  // joint.hydraulic_opening
  static constexpr std::array<Spelling<hydro::HydraulicOpening>, 2> table{{
      {hydro::HydraulicOpening::face, "face"},
      {hydro::HydraulicOpening::local, "local"},
  }};
};

template <>
struct Spellings<coupling::RampedLoad> {  // coupling.ramp
  static constexpr std::array<Spelling<coupling::RampedLoad>, 2> table{{
      {coupling::RampedLoad::whole, "whole"},
      {coupling::RampedLoad::overpressure, "overpressure"},
  }};
};

template <>
struct Spellings<coupling::PermeabilityLaw> {  // flow.permeability_law
  static constexpr auto table = [] {
    std::array<Spelling<coupling::PermeabilityLaw>, coupling::kPermeabilityLaws.size()> spelled{};
    for (std::size_t i = 0; i < spelled.size(); ++i)
      spelled[i] = {coupling::kPermeabilityLaws[i].law, coupling::kPermeabilityLaws[i].name};
    return spelled;
  }();
};

// `value` as the scenario file spells it.
template <typename Enum>
constexpr std::string_view spell(Enum value) {
  for (const Spelling<Enum>& s : Spellings<Enum>::table)
    if (s.value == value) return s.text;
  return {};
}

}  // namespace hydrodda::scenario
