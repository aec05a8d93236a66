#pragma once
// The times at which a scenario's loads given as (time, value) tables have their rows
// (docs/scenario.md, "Loads over time"): a coupled run's load steps, a flow-only run's time.

#include <vector>

#include "scenario/scenario.hpp"

namespace hydrodda::scenario {

// Every row time of every table among the flow boundaries' values, the tractions and the point
// loads, sorted, each once; empty when every load is a constant.
std::vector<double> find_load_times(const Scenario& s);

// The time of the last row of any table: where every table has reached its last value (0 when
// every load is a constant).
double find_final_load_time(const Scenario& s);

}  // namespace hydrodda::scenario
