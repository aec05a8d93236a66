#include "output/quantity_label.hpp"

#include <fmt/format.h>

#include <charconv>

namespace hydrodda::output {

namespace {

bool ends_with(const std::string& text, std::string_view end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

Quantity name_quantity(const std::string& path, const std::vector<std::string>& boundary_names) {
  // The last part of the path names the quantity; the unit is the scenario's (SI) or summary.json's.
  struct Known {
    std::string_view ending, quantity, unit;
  };
  static constexpr Known known[] = {
      {".normalised_conductivity", "K_eff / K_matrix", ""},
      {".effective_conductivity", "K_eff", "m/s"},
      {".displacement.0", "x displacement", "m"},
      {".displacement.1", "y displacement", "m"},
      {".rotation", "rotation", "rad"},
      {".head", "head", "m"},
      {".pressure", "pressure", "Pa"},
      {".flux", "normal flux", "m/s"},
      {".permeability", "permeability", "m²"},
      {".normal_end", "normal traction at the end", "Pa"},
      {".normal", "normal traction", "Pa"},
      {".shear", "shear traction", "Pa"},
      {".density", "density", "kg/m³"},
      {".young", "Young's modulus", "Pa"},
      {".poisson", "Poisson's ratio", ""},
      {".friction_angle", "friction angle", "°"},
      {".cohesion", "cohesion", "Pa"},
      {".tensile_strength", "tensile strength", "Pa"},
      {".viscosity", "viscosity", "Pa s"},
      {"initial_aperture", "initial aperture", "m"},
      {"coupling.max_iterations", "coupling iterations allowed", ""},
      {"coupling.relaxation", "relaxation factor", ""},
      {"mechanics.time_step", "time step", "s"},
      {"mechanics.end_time", "end time", "s"},
  };
  // summary.json's flow through a named boundary, outward (m²/s per metre of thickness).
  if (path.rfind("flow.boundaries.", 0) == 0 && path.find('.', 16) == std::string::npos)
    return {"flow out of " + path.substr(16), "m²/s"};
  for (const Known& k : known) {
    if (!ends_with(path, k.ending)) continue;
    // What the quantity belongs to: a named boundary, region or measure point.
    std::string owner;
    const std::string rest = path.substr(0, path.size() - k.ending.size());
    const std::size_t open = rest.rfind('['), dot = rest.rfind('.');
    if (rest.rfind("flow.boundary[", 0) == 0 && open != std::string::npos) {
      // The path is the user's, not yet followed: "boundary[x]" names no boundary.
      std::size_t index = 0;
      const char* first = rest.data() + open + 1;
      const auto [end, error] = std::from_chars(first, rest.data() + rest.size(), index);
      const bool read = error == std::errc{} && end != first;
      owner = read && index < boundary_names.size() ? " at " + boundary_names[index] : "";
    } else if ((rest.rfind("flow.regions.", 0) == 0 || rest.rfind("measure.", 0) == 0) && dot != std::string::npos) {
      owner = " of " + rest.substr(dot + 1);
    }
    return {fmt::format("{}{}", k.quantity, owner), k.unit};
  }
  return {path, ""};
}

std::string quantity_label(const std::string& path, const std::vector<std::string>& boundary_names) {
  const Quantity q = name_quantity(path, boundary_names);
  return q.unit.empty() ? q.name : fmt::format("{} ({})", q.name, q.unit);
}

}  // namespace hydrodda::output
