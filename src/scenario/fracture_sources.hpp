#pragma once
// The scenario's fracture traces beyond those listed: generated joint sets
// ([[geometry.joint_set]]) and the rows of a fractures file (geometry.fractures_file).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scenario/table_view.hpp"

namespace hydrodda::scenario {

// Every [[geometry.joint_set]] table of `geometry_table`, checked, into geometry.joint_sets.
void read_joint_sets(ReadContext& context, const TableView& geometry_table, GeometryDefinition& geometry);

// geometry.fractures_file, resolved against the scenario's folder, and its rows.
void read_fractures_file(ReadContext& context, const TableView& geometry_table,
                         const std::filesystem::path& scenario_file, GeometryDefinition& geometry);

// An error at each row of a fractures file (`file`) whose trace lies wholly outside the domain.
void check_file_traces_meet_domain(ReadContext& context, const std::string& file, const std::string& key,
                                   const GeometryDefinition& geometry);

// The rows of a fractures file: `x1,y1,x2,y2` per line (what DFN tools export), an optional
// header as the first line (a row with no number in it), blank lines and lines starting with
// '#' skipped. Each bad row (a field not a number, or not finite) is an error naming `file`,
// its line and `key`.
std::vector<FileFracture> parse_fracture_rows(std::string_view text, const std::string& file, const std::string& key,
                                              std::vector<Diagnostic>& errors);

}  // namespace hydrodda::scenario
