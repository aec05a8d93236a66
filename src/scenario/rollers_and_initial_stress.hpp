#pragma once
// [[mechanics.roller]] and [mechanics.initial_stress]: the boundaries that hold a model and the
// stress it starts in.

#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// Every [[mechanics.roller]] of `mechanics_table` into mechanics.rollers.
void read_rollers(ReadContext& context, const TableView& mechanics_table, MechanicsDefinition& mechanics);

// [mechanics.initial_stress], when present, into mechanics.initial_stress.
void read_initial_stress(ReadContext& context, const TableView& mechanics_table, MechanicsDefinition& mechanics);

}  // namespace hydrodda::scenario
