#pragma once
// The bounds of values a run can use, each far beyond what rock and water do and well inside
// what the engines' 16 digits hold: beyond them a run fails on overflow, underflow or
// round-off, far from the value to blame (docs/scenario.md, "Bounds").

namespace hydrodda::scenario {

// Young's modulus, Pa: softer than any soil (a soft clay is 1e6) to ten times diamond's.
inline constexpr double kMinYoung = 1e3;
inline constexpr double kMaxYoung = 1e13;
// Kozeny–Carman grain diameter, m: a tenth of the finest clay platelet to a boulder.
inline constexpr double kMinGrainDiameter = 1e-8;
inline constexpr double kMaxGrainDiameter = 1.0;
// Permeability, m²: pores some 10 cm across, where flow has long stopped being Darcy's.
inline constexpr double kMaxPermeability = 1e-3;
// Contact penalty over the stiffest Young's modulus (× 1 m): its default is 50; a million
// times stiffer contacts hold nothing more, and leave the stiffness matrix past its digits.
inline constexpr double kMaxPenaltyPerYoung = 1e6;
// Allowed step displacement over half the model's height: below, the DDA's own penetration
// tolerance (1e-4 of that) falls under what positions resolve.
inline constexpr double kMinDisplacementRatio = 1e-5;
// Penetration tolerance over the model's size: positions resolve 2.2e-10 of it at the
// farthest from the origin a model may lie (kMaxOriginDistance sizes).
inline constexpr double kMinPenetrationPerSize = 1e-9;
// Stress and pore pressure, Pa: 10 GPa, beyond the strength of any rock (the pressure some
// 300 km down); a head lies within that pressure's height of water (1e6 m) of the model.
inline constexpr double kMaxStress = 1e10;
inline constexpr double kMaxPressureHead = 1e6;
// Specific storage and fluid compressibility, 1/Pa: a hundred times the softest clay's (1e-7),
// a bulk modulus of 100 kPa.
inline constexpr double kMaxStorage = 1e-5;
// The most steps a transient run may take at its largest step, end_time / max_time_step: a
// million steps of a 10^5-node mesh are hours.
inline constexpr double kMaxTransientSteps = 1e6;

}  // namespace hydrodda::scenario
