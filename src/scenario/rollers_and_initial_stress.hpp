#pragma once
// [[mechanics.roller]] and [mechanics.initial_stress]: the boundaries that hold a model and the
// stress it starts in.

#include "scenario/scenario_queries.hpp"
#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// Every [[mechanics.roller]] of `mechanics_table` into mechanics.rollers.
void read_rollers(ReadContext& context, const TableView& mechanics_table, MechanicsDefinition& mechanics);

// [mechanics.initial_stress], when present, into mechanics.initial_stress.
void read_initial_stress(ReadContext& context, const TableView& mechanics_table, MechanicsDefinition& mechanics);

// An in-situ stress that grows less compressive downward than the rock's weight and the boundary
// heads could make it is an error naming mechanics.initial_stress.gradient (after every section
// has been read).
void check_initial_stress_gradient(ReadContext& context, const Scenario& scenario);

// An in-situ stress whose gradient takes a component beyond ±kMaxStress within the model's
// height is an error naming mechanics.initial_stress.gradient.
void check_initial_stress_across_model(ReadContext& context, const Scenario& scenario);

}  // namespace hydrodda::scenario
