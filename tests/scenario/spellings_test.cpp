#include "scenario/spellings.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "scenario/overrides.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::scenario {
namespace {

const std::filesystem::path kSixBlock =
    std::filesystem::path(HYDRODDA_SOURCE_DIR) / "scenarios/paper/six_block_lr_rl.toml";

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every value of Enum (0 .. count − 1) once in its table, each with its own spelling.
template <typename Enum>
void expect_one_spelling_each(int count) {
  const auto& table = Spellings<Enum>::table;
  ASSERT_EQ(table.size(), static_cast<std::size_t>(count));
  std::set<Enum> values;
  std::set<std::string_view> texts;
  for (const Spelling<Enum>& s : table) {
    values.insert(s.value);
    texts.insert(s.text);
    EXPECT_FALSE(s.text.empty());
    EXPECT_EQ(spell(s.value), s.text);
  }
  EXPECT_EQ(values.size(), table.size());
  EXPECT_EQ(texts.size(), table.size());
  for (int v = 0; v < count; ++v) EXPECT_EQ(values.count(static_cast<Enum>(v)), 1u) << v;
}

TEST(ScenarioSpellings, EachValueHasOneSpellingOfItsOwn) {
  expect_one_spelling_each<dda::Analysis>(2);
  expect_one_spelling_each<dda::Plane>(2);
  expect_one_spelling_each<dda::ContactMethod>(2);
  expect_one_spelling_each<hydro::PressureConvention>(2);
  expect_one_spelling_each<hydro::BoundaryKind>(3);
  expect_one_spelling_each<coupling::Acceleration>(3);
  expect_one_spelling_each<geometry::TessellationKind>(2);
  expect_one_spelling_each<coupling::PermeabilityLaw>(static_cast<int>(coupling::kPermeabilityLaws.size()));
}

TEST(ScenarioSpellings, ThePermeabilityLawsAreSpelledAsTheLawsNameThemselves) {
  for (const coupling::PermeabilityLawInfo& law : coupling::kPermeabilityLaws) EXPECT_EQ(spell(law.law), law.name);
  EXPECT_EQ(spell(coupling::PermeabilityLaw::kozeny_carman), "kozeny-carman");
  EXPECT_EQ(spell(coupling::PermeabilityLaw::cubic), "cubic");
}

// The scenario read with `key` set to `text`.
Scenario read_with(const std::string& key, std::string_view text) {
  std::string quoted = "\"";
  quoted.append(text).push_back('"');
  const std::string changed = apply_overrides(read_text(kSixBlock), kSixBlock, {{key, quoted}});
  return parse_scenario(changed, kSixBlock);
}

// Each spelling of the table reads as its value under `key`.
template <typename Enum, typename Field>
void expect_read_back(const std::string& key, Field field) {
  for (const Spelling<Enum>& s : Spellings<Enum>::table) {
    SCOPED_TRACE(key + " = \"" + std::string(s.text) + "\"");
    EXPECT_EQ(field(read_with(key, s.text)), s.value);
  }
}

TEST(ScenarioSpellings, EachSpellingReadsAsItsValue) {
  expect_read_back<dda::Analysis>("mechanics.analysis", [](const Scenario& s) { return s.mechanics->analysis; });
  expect_read_back<dda::Plane>("mechanics.plane", [](const Scenario& s) { return s.mechanics->plane; });
  expect_read_back<dda::ContactMethod>("mechanics.contact", [](const Scenario& s) { return s.mechanics->contact; });
  expect_read_back<hydro::PressureConvention>("flow.pressure", [](const Scenario& s) { return s.flow->pressure; });
  expect_read_back<coupling::PermeabilityLaw>("flow.permeability_law",
                                              [](const Scenario& s) { return s.flow->permeability_law; });
  expect_read_back<coupling::Acceleration>("coupling.acceleration",
                                           [](const Scenario& s) { return s.coupling.acceleration; });
}

TEST(ScenarioSpellings, AValueNotInTheTableIsRefusedNamingThemAll) {
  try {
    read_with("coupling.acceleration", "aitkin");
    FAIL() << "an unknown acceleration was read";
  } catch (const ScenarioError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("\"aitkin\" is not one of \"none\", \"aitken\", \"anderson\" (did you mean \"aitken\"?)"),
              std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace hydrodda::scenario
