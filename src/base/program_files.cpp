#include "base/program_files.hpp"

#include <system_error>

namespace hydrodda::base {

std::filesystem::path find_beside_program(std::string_view name, const std::filesystem::path& built) {
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path beside = program.parent_path() / name;
    if (std::filesystem::exists(beside, error)) return beside;
  }
  return built;
}

}  // namespace hydrodda::base
