#pragma once
// Reading transient flow ([flow.transient], [[flow.probe]]) and the checks it needs across the
// scenario (docs/scenario.md, "Transient flow"). Each refusal names the file, line and key.

#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// [flow.transient] into flow.transient; `lowest_head` and `highest_head` bound initial_head as
// they bound a boundary's head.
void read_transient(ReadContext& context, const TableView& flow_table, double lowest_head, double highest_head,
                    FlowDefinition& flow);
// [[flow.probe]] into flow.probes.
void read_probes(ReadContext& context, const TableView& flow_table, FlowDefinition& flow);
// Across sections: a transient run needs storage somewhere; coupled transient runs are not
// built yet; probes lie in the fluid domain.
void check_transient(ReadContext& context, const TableView& root, const Scenario& scenario);

}  // namespace hydrodda::scenario
