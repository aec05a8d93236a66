#include "base/program_files.hpp"

#include <dlfcn.h>

#include <stdexcept>
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

Plugin::Plugin(std::string_view name, const std::filesystem::path& built, std::string what, bool global)
    : path_(find_beside_program(name, built)), what_(std::move(what)) {
  handle_ = ::dlopen(path_.c_str(), RTLD_NOW | (global ? RTLD_GLOBAL : RTLD_LOCAL));
  if (!handle_) {
    const char* why = ::dlerror();
    throw std::runtime_error("cannot load " + what_ + " '" + path_.string() + "': " + (why ? why : "unknown error"));
  }
}

void* Plugin::address_of(const char* symbol) const {
  void* address = ::dlsym(handle_, symbol);
  if (!address)
    throw std::runtime_error(what_ + " '" + path_.string() + "' lacks its entry point " + symbol);
  return address;
}

}  // namespace hydrodda::base
