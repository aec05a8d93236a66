// libFuzzer target: the scenario reader must turn any byte string into a Scenario or a
// ScenarioError, never a crash, a hang, another exception or undefined behaviour.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    hydrodda::scenario::parse_scenario(text, "fuzz/case.toml");
  } catch (const hydrodda::scenario::ScenarioError&) {
    // Bad input, reported: the expected outcome for most inputs.
  }
  return 0;
}
