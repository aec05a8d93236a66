#include "output/item_list.hpp"

namespace hydrodda::output {

std::string list_items(std::span<const std::string> items, const RunFolder* folder, std::string_view file_name,
                       std::string_view separator, std::span<const std::string> file_items) {
  std::string line;
  const std::size_t named = items.size() <= kListedItems ? items.size() : kListedItems;
  for (std::size_t i = 0; i < named; ++i) {
    if (i > 0) line += separator;
    line += items[i];
  }
  if (named == items.size()) return line;
  line += " and " + std::to_string(items.size() - named) + " more";
  if (!folder) return line;
  std::string all;
  for (const std::string& item : file_items.empty() ? items : file_items) all += item + "\n";
  try {
    folder->write(file_name, all);
  } catch (const RunFolderError&) {
    return line;  // the warning is still worth its line
  }
  return line + " (all " + std::to_string(items.size()) + " in " + folder->file(file_name).string() + ")";
}

}  // namespace hydrodda::output
