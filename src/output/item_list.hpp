#pragma once
// A warning or message that lists items (blocks, [[mesh.refine]] tables, summary paths) names a
// few of them in its line and writes the full list to a file in the run folder, which it names:
// a line of a hundred tables is read by no one.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "output/run_folder.hpp"

namespace hydrodda::output {

// The most items a line names.
inline constexpr std::size_t kListedItems = 5;

// The items joined by `separator` when there are at most kListedItems; else the first of them,
// "and N more", and where the full list is: `file_name` in `folder`, one item a line (or each
// of `file_items` as it is, when given: text to paste), written here ("(all 100 in
// run/unresolved_tips.toml)"). Without a folder (or when the file cannot be written) the line
// says only how many more there are.
std::string list_items(std::span<const std::string> items, const RunFolder* folder, std::string_view file_name,
                       std::string_view separator = ", ", std::span<const std::string> file_items = {});

}  // namespace hydrodda::output
