// hydrodda.Simulation: the run layer's models (FlowModel, MechanicsModel, CoupledModel) built
// from a scenario and advanced from Python, their fields as NumPy arrays between steps and
// passes. Nothing is written to files.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <variant>

#include "coupling/staggered_loop.hpp"
#include "output/summary.hpp"
#include "python/bindings.hpp"
#include "python/python_callbacks.hpp"
#include "run/coupled_model.hpp"
#include "run/flow_model.hpp"
#include "run/mechanics_model.hpp"
#include "run/run.hpp"

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

// The fluid mesh and, once solved, its fields: nodes (N, 2) m, triangles (T, 3) node indices,
// head and pressure per node, flux (T, 2) m/s and permeability (T) m² per triangle.
py::dict fluid_fields(const mesh::TriangleMesh& mesh, const hydro::FlowSolution* flow,
                      const std::vector<double>& permeability) {
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
  return fields;
}

// The blocks as they stand: polygons (a list of (n, 2) arrays, m), centroid and displacement
// (B, 2) m, rotation (B) rad, stress (B, 3) σxx, σyy, τxy Pa, area (B) m².
py::dict block_fields(const dda::System& system) {
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
  return fields;
}

// Every contact: block_i, vertex, block_j, edge (int arrays: vertex `vertex` of block_i against
// edge `edge` of block_j), state ("open", "sliding", "locked"), penetration (m, > 0 overlap) and
// normal_force (N/m, compression positive).
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

py::object summary_dict(const output::RunSummary& summary) {
  return py::module_::import("json").attr("loads")(output::format_summary(summary));
}

// A scenario's model, stepped by hand.
class Simulation {
 public:
  explicit Simulation(const PythonScenario& scenario) {
    py::gil_scoped_release released;
    switch (run::kind_of(scenario.definition)) {
      case run::RunKind::flow: model_ = std::make_unique<run::FlowModel>(scenario.definition); break;
      case run::RunKind::mechanics: model_ = std::make_unique<run::MechanicsModel>(scenario.definition); break;
      case run::RunKind::coupled: model_ = std::make_unique<run::CoupledModel>(scenario.definition); break;
    }
  }

  std::string kind() const {
    return std::holds_alternative<Flow>(model_) ? "flow" : std::holds_alternative<Mechanics>(model_) ? "mechanics" : "coupled";
  }

  // Flow only: the steady solve.
  void solve() {
    run::FlowModel& model = *expect<Flow>("solve()");
    py::gil_scoped_release released;
    model.solve();
  }

  // Mechanics only: up to `count` DDA steps, fewer when the run reaches its end; the number
  // taken. Ctrl-C stops after the step under way (KeyboardInterrupt).
  long long step(long long count) {
    run::MechanicsModel& model = *expect<Mechanics>("step()");
    PythonCallbacks callbacks{py::none()};
    const run::Callbacks stop = callbacks.callbacks();
    long long taken = 0;
    {
      py::gil_scoped_release released;
      while (taken < count && !model.finished() && !stop.stop_requested()) {
        model.step();
        ++taken;
      }
    }
    callbacks.raise_pending();
    return taken;
  }

  // Coupled: one coupling pass; what it measured. Ctrl-C abandons the pass, the model left at
  // its last finished one (KeyboardInterrupt).
  py::dict run_pass() {
    run::CoupledModel& model = *expect<Coupled>("run_pass()");
    PythonCallbacks callbacks{py::none()};
    model.set_stop_request(callbacks.callbacks().stop_requested);
    std::optional<coupling::PassReport> report;
    try {
      py::gil_scoped_release released;
      report = model.run_pass();
    } catch (const coupling::PassInterrupted&) {
      model.set_stop_request({});
      callbacks.raise_pending();
      throw;
    }
    model.set_stop_request({});
    converged_ = report->converged;
    py::dict fields;
    fields["iteration"] = report->iteration;
    fields["time"] = report->time;
    fields["head_change"] = report->head_change;
    fields["displacement_change"] = report->displacement_change;
    fields["largest_opening"] = report->largest_opening;
    fields["mean_porosity"] = report->mean_porosity;
    fields["max_permeability"] = report->max_permeability;
    fields["converged"] = report->converged;
    return fields;
  }

  bool finished() const {
    if (const auto* m = std::get_if<Mechanics>(&model_)) return (*m)->finished();
    if (std::holds_alternative<Coupled>(model_)) return converged_;
    return !std::get<Flow>(model_)->flow().head.empty();
  }

  py::dict fluid() const {
    if (const auto* f = std::get_if<Flow>(&model_))
      return fluid_fields((*f)->mesh(), &(*f)->flow(), (*f)->permeability());
    const run::CoupledModel& model = *expect_const<Coupled>("fluid");
    const coupling::StaggeredLoop& loop = model.loop();
    py::dict fields = fluid_fields(model.mesh(), &loop.flow(), loop.permeability());
    if (!loop.porosity().porosity.empty()) fields["porosity"] = column(loop.porosity().porosity);
    return fields;
  }

  py::dict blocks() const { return block_fields(system("blocks")); }
  py::dict contacts() const { return contact_fields(system("contacts")); }

  py::object summary() const {
    return std::visit([](const auto& model) { return summary_dict(model->summary()); }, model_);
  }

 private:
  using Flow = std::unique_ptr<run::FlowModel>;
  using Mechanics = std::unique_ptr<run::MechanicsModel>;
  using Coupled = std::unique_ptr<run::CoupledModel>;

  template <class Model>
  Model& expect(const char* what) {
    if (auto* m = std::get_if<Model>(&model_)) return *m;
    throw std::logic_error(std::string(what) + " is not for a " + kind() + " simulation");
  }
  template <class Model>
  const Model& expect_const(const char* what) const {
    if (const auto* m = std::get_if<Model>(&model_)) return *m;
    throw std::logic_error(std::string(what) + " is not for a " + kind() + " simulation");
  }
  const dda::System& system(const char* what) const {
    if (const auto* m = std::get_if<Mechanics>(&model_)) return (*m)->system();
    return expect_const<Coupled>(what)->mechanics();
  }

  std::variant<Flow, Mechanics, Coupled> model_;
  bool converged_ = false;  // coupled: the last pass met the tolerance
};

}  // namespace

void bind_simulation(py::module_& module) {
  py::class_<Simulation>(module, "Simulation", "A scenario's model advanced by hand; its fields as NumPy arrays.")
      .def(py::init<const PythonScenario&>(), py::arg("scenario"))
      .def_property_readonly("kind", &Simulation::kind)
      .def("solve", &Simulation::solve, "Flow only: the steady solve.")
      .def("step", &Simulation::step, py::arg("count") = 1,
           "Mechanics only: up to `count` DDA steps (fewer at the run's end); the number taken.")
      .def("run_pass", &Simulation::run_pass, "Coupled: one coupling pass; what it measured, as a dict.")
      .def_property_readonly("finished", &Simulation::finished,
                             "steps or end_time reached; coupling converged; flow solved")
      .def_property_readonly("fluid", &Simulation::fluid)
      .def_property_readonly("blocks", &Simulation::blocks)
      .def_property_readonly("contacts", &Simulation::contacts)
      .def_property_readonly("summary", &Simulation::summary, "summary.json's content for the state now (no timings)");
}

}  // namespace hydrodda::python
