// The programs allocate through jemalloc with its memory advised for transparent huge pages
// (src/allocator_options.cpp): this test program, as it reports of itself through mallctl,
// and the hydrodda program, as jemalloc's statistics at its exit report. Whether the kernel
// then grants huge pages is its own affair (it may keep them off), so it is not asserted.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "run_program.hpp"

#ifdef HYDRODDA_JEMALLOC
#include <jemalloc/jemalloc.h>
#endif

namespace {

#ifdef HYDRODDA_JEMALLOC
std::string option(const char* name) {
  const char* value = nullptr;
  std::size_t length = sizeof(value);
  if (mallctl(name, &value, &length, nullptr, 0) != 0 || value == nullptr) return "(not available)";
  return value;
}
#endif

TEST(Allocator, ProgramsAllocateThroughJemallocOnHugePages) {
#ifndef HYDRODDA_JEMALLOC
  GTEST_SKIP() << "built with the sanitizers' allocator";
#else
  if (std::getenv("MALLOC_CONF") != nullptr) GTEST_SKIP() << "MALLOC_CONF overrides the options";
  EXPECT_EQ(option("opt.thp"), "always");
  EXPECT_EQ(option("opt.metadata_thp"), "always");
  // stats_print: jemalloc prints its statistics, options included, when the program exits.
  const auto result = hydrodda::testing::run_command("MALLOC_CONF=stats_print:true " HYDRODDA_BINARY " --version");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("opt.thp: \"always\""), std::string::npos) << result.output.substr(0, 2000);
  EXPECT_NE(result.output.find("opt.metadata_thp: \"always\""), std::string::npos) << result.output.substr(0, 2000);
#endif
}

}  // namespace
