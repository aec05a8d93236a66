// A model's fields as NumPy arrays (model_fields.hpp).

#include "python/model_fields.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "run/coupled_model.hpp"
#include "run/flow_model.hpp"
#include "run/mechanics_model.hpp"
#include "run/run_summary.hpp"

namespace hydrodda::python {

namespace {

using Array = py::array_t<double>;

// An (n, width) array of `n` rows that `row(i, j)` fills.
template <class Row>
Array table(std::size_t n, std::size_t width, Row row) {
  Array array(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(width)});
  auto view = array.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < width; ++j) view(i, j) = row(i, j);
  return array;
}

Array column(const std::vector<double>& values) { return Array(static_cast<py::ssize_t>(values.size()), values.data()); }

Array points(const std::vector<geometry::Point>& values) {
  return table(values.size(), 2, [&](std::size_t i, std::size_t j) { return j == 0 ? values[i].x : values[i].y; });
}

}  // namespace

py::dict fluid_fields(const mesh::TriangleMesh& mesh, const hydro::FlowSolution* flow,
                      const std::vector<double>& permeability, const std::vector<double>* porosity) {
  py::dict fields;
  fields["nodes"] = points(mesh.nodes);
  py::array_t<int> triangles(std::vector<py::ssize_t>{mesh.triangle_count(), 3});
  auto view = triangles.mutable_unchecked<2>();
  for (int t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) view(t, k) = mesh.triangles[t][k];
  fields["triangles"] = triangles;
  fields["permeability"] = column(permeability);
  if (flow != nullptr && !flow->head.empty()) {
    fields["head"] = column(flow->head);
    fields["pressure"] = column(flow->pressure);
    fields["flux"] = points(flow->flux);
  }
  if (porosity != nullptr && !porosity->empty()) fields["porosity"] = column(*porosity);
  return fields;
}

py::dict block_fields(const dda::System& system, const scenario::Scenario& scenario) {
  const auto n = static_cast<std::size_t>(system.block_count());
  py::list polygons;
  for (int b = 0; b < system.block_count(); ++b) polygons.append(points(system.polygon(b)));
  py::dict fields;
  fields["polygons"] = polygons;
  fields["centroid"] = table(n, 2, [&](std::size_t b, std::size_t j) {
    const geometry::Point c = system.centroid(static_cast<int>(b));
    return j == 0 ? c.x : c.y;
  });
  fields["displacement"] = table(n, 2, [&](std::size_t b, std::size_t j) {
    const geometry::Point d = system.displacement(static_cast<int>(b));
    return j == 0 ? d.x : d.y;
  });
  fields["rotation"] = table(n, 1, [&](std::size_t b, std::size_t) { return system.rotation(static_cast<int>(b)); })
                           .attr("reshape")(n);
  fields["stress"] = table(n, 3, [&](std::size_t b, std::size_t j) { return system.stress(static_cast<int>(b))[j]; });
  fields["area"] = table(n, 1, [&](std::size_t b, std::size_t) { return system.area(static_cast<int>(b)); })
                       .attr("reshape")(n);
  py::list material;
  for (int b = 0; b < system.block_count(); ++b) material.append(run::block_material_name(scenario, system, b));
  fields["material"] = py::array(material);
  return fields;
}

py::dict contact_fields(const dda::System& system) {
  const std::vector<dda::ContactInfo> contacts = system.contacts();
  const auto n = static_cast<py::ssize_t>(contacts.size());
  py::array_t<int> block_i(n), vertex(n), block_j(n), edge(n);
  Array penetration(n), normal_force(n);
  py::list state;
  for (py::ssize_t c = 0; c < n; ++c) {
    const dda::ContactInfo& info = contacts[static_cast<std::size_t>(c)];
    block_i.mutable_at(c) = info.key.block_i;
    vertex.mutable_at(c) = info.key.vertex;
    block_j.mutable_at(c) = info.key.block_j;
    edge.mutable_at(c) = info.key.edge;
    penetration.mutable_at(c) = info.penetration;
    normal_force.mutable_at(c) = info.normal_force;
    state.append(info.state == dda::ContactState::open      ? "open"
                 : info.state == dda::ContactState::sliding ? "sliding"
                                                            : "locked");
  }
  py::dict fields;
  fields["block_i"] = block_i;
  fields["vertex"] = vertex;
  fields["block_j"] = block_j;
  fields["edge"] = edge;
  fields["state"] = py::array(state);
  fields["penetration"] = penetration;
  fields["normal_force"] = normal_force;
  return fields;
}

py::dict fracture_fields(const fractures::FractureState& state) {
  const auto n = static_cast<py::ssize_t>(state.fractures.size());
  py::array_t<int> id(n), set(n), number(n);
  py::array_t<bool> open(n);
  Array length(n), open_length(n), open_share(n), mean_aperture(n), max_aperture(n), max_shear(n), hydraulic_aperture(n),
      normal_stress(n), tip_opening_angle(n), flow(n);
  py::list origin;
  for (py::ssize_t i = 0; i < n; ++i) {
    const fractures::FractureResult& r = state.fractures[static_cast<std::size_t>(i)];
    id.mutable_at(i) = r.id;
    origin.append(fractures::origin_name(r.origin.source));
    set.mutable_at(i) = r.origin.source == geometry::TraceSource::joint_set ? r.origin.set : -1;
    number.mutable_at(i) = r.origin.number;
    length.mutable_at(i) = r.length;
    open_length.mutable_at(i) = r.open_length;
    open.mutable_at(i) = r.open;
    open_share.mutable_at(i) = r.open_share;
    mean_aperture.mutable_at(i) = r.mean_aperture;
    max_aperture.mutable_at(i) = r.max_aperture;
    max_shear.mutable_at(i) = r.max_shear;
    hydraulic_aperture.mutable_at(i) = r.hydraulic_aperture;
    normal_stress.mutable_at(i) = r.normal_stress;
    tip_opening_angle.mutable_at(i) = r.tip_opening_angle;
    flow.mutable_at(i) = r.flow ? *r.flow : std::numeric_limits<double>::quiet_NaN();
  }
  py::dict fields;
  fields["id"] = id;
  fields["origin"] = py::array(origin);
  fields["set"] = set;
  fields["number"] = number;
  fields["length"] = length;
  fields["open_length"] = open_length;
  fields["open"] = open;
  fields["open_share"] = open_share;
  fields["mean_aperture"] = mean_aperture;
  fields["max_aperture"] = max_aperture;
  fields["max_shear"] = max_shear;
  fields["hydraulic_aperture"] = hydraulic_aperture;
  fields["normal_stress"] = normal_stress;
  fields["tip_opening_angle"] = tip_opening_angle;
  fields["flow"] = flow;
  return fields;
}

py::dict fields_at_end(const run::ModelAtEnd& end) {
  py::dict fields;
  if (const auto* flow = std::get_if<const run::FlowModel*>(&end.model)) {
    const run::FlowModel& model = **flow;
    fields["fluid"] = fluid_fields(model.mesh(), &model.flow(), model.permeability());
  } else if (const auto* mechanics = std::get_if<const run::MechanicsModel*>(&end.model)) {
    fields["blocks"] = block_fields((*mechanics)->system(), (*mechanics)->scenario());
    fields["contacts"] = contact_fields((*mechanics)->system());
  } else {
    const run::CoupledModel& model = *std::get<const run::CoupledModel*>(end.model);
    const coupling::StaggeredLoop& loop = model.loop();
    fields["fluid"] = fluid_fields(model.mesh(), loop.has_flow() ? &loop.flow() : nullptr, loop.permeability(),
                                   &loop.porosity().porosity);
    fields["blocks"] = block_fields(model.mechanics(), model.scenario());
    fields["contacts"] = contact_fields(model.mechanics());
  }
  if (end.fractures != nullptr) fields["fractures"] = fracture_fields(*end.fractures);
  return fields;
}

}  // namespace hydrodda::python
