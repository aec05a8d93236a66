// hydrodda.Simulation: the run layer's models (FlowModel, MechanicsModel, CoupledModel) built
// from a scenario and advanced from Python, their fields as NumPy arrays between steps and
// passes. Nothing is written to files.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <regex>
#include <stdexcept>
#include <thread>
#include <variant>

#include "coupling/staggered_loop.hpp"
#include "fractures/fracture_results.hpp"
#include "geometry/point.hpp"
#include "output/summary.hpp"
#include "python/bindings.hpp"
#include "python/model_fields.hpp"
#include "python/python_callbacks.hpp"
#include "run/coupled_model.hpp"
#include "run/coupled_transient_model.hpp"
#include "run/model_building.hpp"
#include "run/flow_model.hpp"
#include "run/mechanics_model.hpp"
#include "run/mechanics_rest.hpp"
#include "run/run.hpp"
#include "run/run_summary.hpp"
#include "run/scenario_fractures.hpp"
#include "run/threads.hpp"
#include "run/transient_model.hpp"

namespace hydrodda::python {

namespace {

py::object summary_dict(const output::RunSummary& summary) {
  return py::module_::import("json").attr("loads")(output::format_summary(summary));
}

// threads= as hydrodda.run() takes it (its _check_count): None, or a whole number from 1 to
// 4096 (not a bool); anything else is a ValueError that names it.
std::optional<int> checked_thread_count(const py::object& threads) {
  if (threads.is_none()) return std::nullopt;
  const bool whole = py::isinstance<py::int_>(threads) && !py::isinstance<py::bool_>(threads);
  const long long count = whole ? threads.cast<long long>() : 0;
  if (!whole || count < 1 || count > 4096)
    throw py::value_error("threads: must be a whole number from 1 to 4096, got " +
                          py::repr(threads).cast<std::string>());
  return static_cast<int>(count);
}

// One caller of a model at a time. A step, pass or solve runs with the GIL released, so
// another Python thread may call into the same model meanwhile: it waits (the GIL released
// while it waits) until the first is done. A call from inside one under way on the same
// thread (a signal or logging handler) would wait for itself: it is refused.
class ModelLock {
 public:
  class Held {
   public:
    explicit Held(ModelLock& lock) : lock_(lock) {}
    ~Held() {
      lock_.owner_ = std::thread::id();
      lock_.mutex_.unlock();
    }
    Held(const Held&) = delete;
    Held& operator=(const Held&) = delete;

   private:
    ModelLock& lock_;
  };

  // Call with the GIL held.
  [[nodiscard]] Held hold(const char* what) {
    if (owner_ == std::this_thread::get_id())
      throw std::runtime_error(std::string(what) + ": this Simulation is in a call on this thread already (a " +
                               "handler called while it steps cannot use it)");
    if (!mutex_.try_lock()) {
      py::gil_scoped_release released;
      mutex_.lock();
    }
    owner_ = std::this_thread::get_id();
    return Held(*this);
  }

 private:
  std::mutex mutex_;
  std::atomic<std::thread::id> owner_{};
};

// A scenario's model, stepped by hand.
class Simulation {
 public:
  Simulation(const PythonScenario& scenario, const py::object& threads)
      : scenario_(scenario), threads_(checked_thread_count(threads)) {
    run::chosen_thread_count(threads_);  // a bad HYDRODDA_THREADS is refused now, not at the first step
    // Meshing again around the wedge tips is the run's (run_coupled): a model stepped by hand
    // keeps the mesh it was built on.
    if (scenario.definition.mesh && scenario.definition.mesh->refine_tips)
      throw py::value_error(
          "mesh.refine_tips = true: a Simulation keeps the mesh it is built on; hydrodda.run() meshes again around "
          "the wedge tips (or set it false to step the model by hand)");
    PythonCallbacks callbacks{py::none()};  // Ctrl-C in a logging handler while building: raised once built
    {
      py::gil_scoped_release released;
      const run::ThreadsOfThisCall own_threads(threads_);
      switch (run::kind_of(scenario.definition)) {
        case run::RunKind::flow:
          if (scenario.definition.flow->transient) model_ = std::make_unique<run::TransientModel>(scenario.definition);
          else model_ = std::make_unique<run::FlowModel>(scenario.definition);
          break;
        case run::RunKind::mechanics: model_ = std::make_unique<run::MechanicsModel>(scenario.definition); break;
        case run::RunKind::coupled:
          if (scenario.definition.flow->transient)
            model_ = std::make_unique<run::CoupledTransientModel>(scenario.definition);
          else
            model_ = std::make_unique<run::CoupledModel>(scenario.definition);
          break;
      }
    }
    callbacks.raise_pending();
  }

  std::string kind() const {
    return std::holds_alternative<Flow>(model_)               ? "flow"
           : std::holds_alternative<Transient>(model_)        ? "transient"
           : std::holds_alternative<CoupledTransient>(model_) ? "coupled_transient"
           : std::holds_alternative<Mechanics>(model_)        ? "mechanics"
                                                              : "coupled";
  }

  // Flow only: the steady solve.
  void solve() {
    const ModelLock::Held held = lock_.hold("solve()");
    run::FlowModel& model = *expect<Flow>("solve()");
    PythonCallbacks callbacks{py::none()};  // the one solve is not stopped: Ctrl-C is raised after it
    {
      py::gil_scoped_release released;
      const run::ThreadsOfThisCall own_threads(threads_);
      model.solve();
    }
    callbacks.raise_pending();
  }

  // Mechanics: up to `count` DDA steps; transient flow or coupled transient: up to `count` time
  // steps; fewer when the run reaches its end; the number taken. Ctrl-C stops after the step
  // under way (KeyboardInterrupt); a coupled transient step is abandoned, the model left at the
  // last step's end.
  long long step(long long count) {
    const ModelLock::Held held = lock_.hold("step()");
    if (auto* transient = std::get_if<Transient>(&model_)) return step_transient(**transient, count, std::nullopt);
    if (auto* coupled = std::get_if<CoupledTransient>(&model_))
      return step_coupled_transient(**coupled, count, std::nullopt);
    run::MechanicsModel& model = *expect<Mechanics>("step()");
    PythonCallbacks callbacks{py::none()};
    const run::Callbacks stop = callbacks.callbacks();
    long long taken = 0;
    {
      py::gil_scoped_release released;
      const run::ThreadsOfThisCall own_threads(threads_);
      while (taken < count && !model.finished() && !stop.stop_requested()) {
        last_step_ = model.step();
        ++taken;
      }
    }
    callbacks.raise_pending();
    return taken;
  }

  // Coupled: one coupling pass; what it measured. Ctrl-C abandons the pass, the model left at
  // its last finished one (KeyboardInterrupt).
  py::dict run_pass() {
    const ModelLock::Held held = lock_.hold("run_pass()");
    run::CoupledModel& model = *expect<Coupled>("run_pass()");
    PythonCallbacks callbacks{py::none()};
    model.set_stop_request(callbacks.callbacks().stop_requested);
    std::optional<coupling::PassReport> report;
    try {
      py::gil_scoped_release released;
      const run::ThreadsOfThisCall own_threads(threads_);
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
    fields["full_time_step"] = report->full_time_step;
    fields["shortest_time_step"] = report->shortest_time_step;
    return fields;
  }

  // Transient flow: the steps up to time `t`, which must end one of them (an output time, the
  // end time, or any time of the plan: step_times); the number taken.
  long long advance_to(double t) {
    const ModelLock::Held held = lock_.hold("advance_to()");
    if (auto* coupled = std::get_if<CoupledTransient>(&model_)) return advance_coupled_transient(**coupled, t);
    run::TransientModel& model = *expect<Transient>("advance_to()");
    const std::vector<double>& times = model.step_times();
    if (t < model.time())
      throw py::value_error(fmt::format("advance_to({:g}): the simulation is at t = {:g} s already", t, model.time()));
    if (t != model.time() && std::find(times.begin(), times.end(), t) == times.end()) {
      const auto after = std::upper_bound(times.begin(), times.end(), t);
      throw py::value_error(fmt::format(
          "advance_to({:g}): no step ends there (the steps end on the output times, the end time and the times of "
          "step_times); the nearest are {:g} and {} s",
          t, after == times.begin() ? 0.0 : *(after - 1), after == times.end() ? std::string("none after") : fmt::format("{:g}", *after)));
    }
    return step_transient(model, std::numeric_limits<long long>::max(), t);
  }

  double time() const {
    const ModelLock::Held held = lock_.hold("time");
    if (const auto* coupled = std::get_if<CoupledTransient>(&model_)) return (*coupled)->time();
    return expect_const<Transient>("time")->time();
  }

  py::array_t<double> step_times() const {
    const ModelLock::Held held = lock_.hold("step_times");
    const std::vector<double>& times = expect_const<Transient>("step_times")->step_times();
    return py::array_t<double>(static_cast<py::ssize_t>(times.size()), times.data());
  }

  // probes.csv's rows at the time now: (time, name, head, pressure), one per probe.
  py::list probes() const {
    const ModelLock::Held held = lock_.hold("probes");
    py::list rows;
    if (const auto* coupled = std::get_if<CoupledTransient>(&model_)) {
      for (const run::ProbeReading& r : (*coupled)->read_probes())
        rows.append(py::make_tuple((*coupled)->time(), r.name, r.head, r.pressure));
      return rows;
    }
    const run::TransientModel& model = *expect_const<Transient>("probes");
    for (const run::ProbeReading& r : model.read_probes()) rows.append(py::make_tuple(model.time(), r.name, r.head, r.pressure));
    return rows;
  }

  bool finished() const {
    const ModelLock::Held held = lock_.hold("finished");
    return is_finished();
  }

  py::dict fluid() const {
    const ModelLock::Held held = lock_.hold("fluid");
    if (const auto* f = std::get_if<Flow>(&model_))
      return fluid_fields((*f)->mesh(), &(*f)->flow(), (*f)->permeability());
    if (const auto* t = std::get_if<Transient>(&model_))
      return fluid_fields((*t)->model().mesh(), &(*t)->state(), (*t)->model().permeability());
    const run::CoupledModel& model = coupled_model("fluid");
    const coupling::StaggeredLoop& loop = model.loop();
    return fluid_fields(model.mesh(), &loop.flow(), loop.permeability(), &loop.porosity().porosity);
  }

  // The fractures as the blocks stand (with their flow once a coupled pass has solved it);
  // None for a scenario that lists its blocks.
  py::object fractures() {
    const ModelLock::Held held = lock_.hold("fractures");
    const dda::System& blocks = system("fractures");
    const run::ThreadsOfThisCall own_threads(threads_);  // the meter's loops
    if (!meter_) {
      meter_ = run::make_fracture_meter(scenario_.definition);
      if (!meter_) return py::none();
    }
    std::vector<geometry::Polygon> polygons;
    for (int b = 0; b < blocks.block_count(); ++b) polygons.push_back(blocks.polygon(b));
    if (!joint_laws_) joint_laws_ = run::make_joint_aperture_laws(scenario_.definition, meter_->layout().traces);
    fractures::FractureState state =
        meter_->measure(polygons, blocks.penetration_tolerance(), blocks.contacts(), *joint_laws_);
    if (!std::holds_alternative<Mechanics>(model_)) {
      const run::CoupledModel& coupled = coupled_model("fractures");
      if (coupled.loop().has_flow()) {
        if (!flow_zones_) flow_zones_ = meter_->flow_zones(coupled.mesh());
        meter_->add_flow(state, *flow_zones_, coupled.mesh(), coupled.loop().flow());
      }
    }
    return fracture_fields(state);
  }

  // Coupled transient: the bonds broken so far, by time step, as fractures.csv's bond rows (a
  // dict of arrays, one entry per break, in the order they broke).
  py::dict broken_bonds() const {
    const ModelLock::Held held = lock_.hold("broken_bonds");
    const auto& breaks = expect_const<CoupledTransient>("broken_bonds")->broken_bonds();
    const auto n = static_cast<py::ssize_t>(breaks.size());
    py::array_t<int> step(n), fracture(n), bond(n);
    py::array_t<double> time(n), length(n), x1(n), y1(n), x2(n), y2(n);
    py::list type, mode;
    for (py::ssize_t i = 0; i < n; ++i) {
      const run::SteppedBondBreak& b = breaks[static_cast<std::size_t>(i)];
      step.mutable_at(i) = b.step;
      time.mutable_at(i) = b.row.time;
      fracture.mutable_at(i) = b.row.fracture;
      bond.mutable_at(i) = b.row.bond;
      length.mutable_at(i) = geometry::distance(b.row.from, b.row.to);
      type.append(b.row.type);
      mode.append(b.row.mode);
      x1.mutable_at(i) = b.row.from.x;
      y1.mutable_at(i) = b.row.from.y;
      x2.mutable_at(i) = b.row.to.x;
      y2.mutable_at(i) = b.row.to.y;
    }
    py::dict rows;
    rows["step"] = step;
    rows["time"] = time;
    rows["fracture"] = fracture;
    rows["number"] = bond;
    rows["length"] = length;
    rows["type"] = py::array(type);
    rows["mode"] = py::array(mode);
    rows["x1"] = x1;
    rows["y1"] = y1;
    rows["x2"] = x2;
    rows["y2"] = y2;
    return rows;
  }

  // A loading path: a new value of a flow boundary condition or of a traction, from the next
  // solve, step or pass on (the key paths of Scenario.set).
  void set(const std::string& key, const py::handle& value) {
    const ModelLock::Held held = lock_.hold("set()");
    static const std::regex flow_key(R"(flow\.boundary\[\d+\]\.(head|pressure|flux))");
    static const std::regex traction_key(R"(mechanics\.traction\[\d+\]\.(normal|normal_end|shear|shear_end))");
    const bool flow = std::regex_match(key, flow_key);
    if (!flow && !std::regex_match(key, traction_key))
      throw py::value_error("Simulation.set changes a boundary's head, pressure or flux "
                            "(flow.boundary[i].head, ...) or a traction (mechanics.traction[i].normal, "
                            "normal_end, shear, shear_end) between steps or passes, not '" + key +
                            "': change the Scenario and build a new Simulation for anything else");
    if (std::holds_alternative<Transient>(model_) || std::holds_alternative<CoupledTransient>(model_))
      throw py::value_error("Simulation.set: a transient simulation takes its boundary values from its scenario at each "
                            "step's time (a table of (time, value) rows); change the Scenario and build a new Simulation");
    PythonScenario changed = with_value(scenario_, key, value);
    if (flow) {
      if (!changed.definition.flow) throw py::value_error(key + ": this simulation has no [flow]");
      auto boundaries = changed.definition.flow->boundaries;
      if (auto* f = std::get_if<Flow>(&model_)) (*f)->set_flow_boundaries(std::move(boundaries));
      else expect<Coupled>("set('flow...')")->set_flow_boundaries(std::move(boundaries));
    } else {
      if (!changed.definition.mechanics) throw py::value_error(key + ": this simulation has no [mechanics]");
      auto tractions = changed.definition.mechanics->tractions;
      if (auto* m = std::get_if<Mechanics>(&model_)) (*m)->set_tractions(std::move(tractions));
      else expect<Coupled>("set('mechanics...')")->set_tractions(std::move(tractions));
    }
    scenario_ = std::move(changed);
    converged_ = false;
  }

  PythonScenario scenario() const {  // a copy: changing it changes no model
    const ModelLock::Held held = lock_.hold("scenario");
    return scenario_;
  }

  py::dict blocks() const {
    const ModelLock::Held held = lock_.hold("blocks");
    return block_fields(system("blocks"), scenario_.definition);
  }
  py::dict contacts() const {
    const ModelLock::Held held = lock_.hold("contacts");
    return contact_fields(system("contacts"));
  }

  // `converged` as a run's summary.json says it: the model finished (flow solved, steps or end
  // time reached, the coupling loop met its tolerance, a static mechanics model's blocks at
  // rest) and its blocks followed every prescribed displacement (else the run fails, and
  // `message` says which did not).
  py::object summary() const {
    const ModelLock::Held held = lock_.hold("summary");
    output::RunSummary summary = std::visit([](const auto& model) { return model->summary(); }, model_);
    if (std::holds_alternative<CoupledTransient>(model_)) {
      // converged: end_time reached without a failure (else its message says why), as the run says it.
      if (const std::string unreached = run::describe_unreached_displacement(scenario_.definition, system("summary"));
          !unreached.empty()) {
        summary.message = unreached;
        summary.converged = false;
      }
      return summary_dict(summary);
    }
    summary.converged = is_finished();
    if (!std::holds_alternative<Flow>(model_) && !std::holds_alternative<Transient>(model_)) {
      summary.message = run::describe_unreached_displacement(scenario_.definition, system("summary"));
      if (!summary.message.empty()) summary.converged = false;
    }
    // A static mechanics model finished with its blocks still moving has not converged, as its
    // run's summary.json says (run/mechanics_rest.hpp).
    if (const auto* m = std::get_if<Mechanics>(&model_);
        m && summary.converged && (*m)->scenario().mechanics->analysis == dda::Analysis::static_) {
      summary.message = run::describe_motion_at_end((*m)->scenario(), (*m)->system(), last_step_, (*m)->steps());
      summary.converged = summary.message.empty();
    }
    return summary_dict(summary);
  }

 private:
  using Flow = std::unique_ptr<run::FlowModel>;
  using Mechanics = std::unique_ptr<run::MechanicsModel>;
  using Coupled = std::unique_ptr<run::CoupledModel>;
  using Transient = std::unique_ptr<run::TransientModel>;
  using CoupledTransient = std::unique_ptr<run::CoupledTransientModel>;

  // Up to `count` steps, and none past `until` when given; Ctrl-C stops after the step under way.
  long long step_transient(run::TransientModel& model, long long count, std::optional<double> until) {
    PythonCallbacks callbacks{py::none()};
    const run::Callbacks stop = callbacks.callbacks();
    long long taken = 0;
    {
      py::gil_scoped_release released;
      const run::ThreadsOfThisCall own_threads(threads_);
      while (taken < count && !model.finished() && !(until && model.time() >= *until) && !stop.stop_requested()) {
        model.step();
        ++taken;
      }
    }
    callbacks.raise_pending();
    return taken;
  }

  // Up to `count` time steps, and none past `until` when given; Ctrl-C abandons the step under
  // way (the model back at the last step's end) and raises KeyboardInterrupt.
  long long step_coupled_transient(run::CoupledTransientModel& model, long long count, std::optional<double> until) {
    PythonCallbacks callbacks{py::none()};
    const run::Callbacks stop = callbacks.callbacks();
    long long taken = 0;
    {
      py::gil_scoped_release released;
      const run::ThreadsOfThisCall own_threads(threads_);
      while (taken < count && !model.finished() && !(until && model.time() >= *until)) {
        if (model.step(stop.stop_requested) != run::CoupledTransientStepper::Outcome::stepped) break;
        ++taken;
      }
    }
    callbacks.raise_pending();
    return taken;
  }

  // The steps up to `t`, which must be a time they land on: an output time, a load table's row
  // or the end time (find_step_stops), or the time reached.
  long long advance_coupled_transient(run::CoupledTransientModel& model, double t) {
    if (t < model.time())
      throw py::value_error(fmt::format("advance_to({:g}): the simulation is at t = {:g} s already", t, model.time()));
    const std::vector<double>& stops = model.stepper().stops();
    if (t != model.time() && std::find(stops.begin(), stops.end(), t) == stops.end())
      throw py::value_error(fmt::format(
          "advance_to({:g}): no step of a coupled transient simulation surely ends there (its steps' lengths follow "
          "their iterations); they land on the output times, the load tables' rows and the end time: {}",
          t, fmt::join(stops, ", ")));
    return step_coupled_transient(model, std::numeric_limits<long long>::max(), t);
  }

  // The coupled model of a coupled or coupled transient simulation.
  const run::CoupledModel& coupled_model(const char* what) const {
    if (const auto* c = std::get_if<CoupledTransient>(&model_)) return (*c)->model();
    return *expect_const<Coupled>(what);
  }

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
  // Flow solved; steps or end time reached; the coupling loop met its tolerance.
  bool is_finished() const {
    if (const auto* m = std::get_if<Mechanics>(&model_)) return (*m)->finished();
    if (std::holds_alternative<Coupled>(model_)) return converged_;
    if (const auto* t = std::get_if<Transient>(&model_)) return (*t)->finished();
    if (const auto* c = std::get_if<CoupledTransient>(&model_)) return (*c)->finished();
    return !std::get<Flow>(model_)->flow().head.empty();
  }
  const dda::System& system(const char* what) const {
    if (const auto* m = std::get_if<Mechanics>(&model_)) return (*m)->system();
    return coupled_model(what).mechanics();
  }

  mutable ModelLock lock_;   // every call but kind holds it
  PythonScenario scenario_;  // as built, with the changes set() made since
  std::optional<int> threads_;  // threads=: the threads of every call that computes (the results are the same on any)
  std::variant<Flow, Mechanics, Coupled, Transient, CoupledTransient> model_;
  bool converged_ = false;  // coupled: the last pass met the tolerance
  dda::StepReport last_step_;  // mechanics: of the last DDA step taken
  std::optional<fractures::FractureMeter> meter_;                  // made on the first call of fractures
  std::optional<fractures::FractureMeter::FlowZones> flow_zones_;  // likewise, for a coupled model
  std::optional<coupling::JointApertureLaws> joint_laws_;    // likewise
};

}  // namespace

void bind_simulation(py::module_& module) {
  py::class_<Simulation>(module, "Simulation", "A scenario's model advanced by hand; its fields as NumPy arrays.")
      .def(py::init<const PythonScenario&, const py::object&>(), py::arg("scenario"), py::kw_only(),
           py::arg("threads") = py::none(),
           "Builds the scenario's model. `threads`: how many its solves, steps and passes use (default: "
           "HYDRODDA_THREADS, else every core the process may use); the results are the same on any number.")
      .def_property_readonly("kind", &Simulation::kind)
      .def("solve", &Simulation::solve, "Flow only: the steady solve.")
      .def("step", &Simulation::step, py::arg("count") = 1,
           "Mechanics: up to `count` DDA steps; transient flow or coupled transient: up to `count` time steps (fewer "
           "at the run's end); the number taken.")
      .def("advance_to", &Simulation::advance_to, py::arg("time"),
           "Transient flow: the steps up to `time` (s), which must end one (an output time, the end time, or one of "
           "step_times); coupled transient: `time` an output time, a load table's row or the end time; the number "
           "taken.")
      .def_property_readonly("time", &Simulation::time, "Transient flow, coupled transient: the time reached (s)")
      .def_property_readonly("step_times", &Simulation::step_times,
                             "Transient flow: the times its steps end on, to end_time (s)")
      .def_property_readonly("probes", &Simulation::probes,
                             "Transient flow, coupled transient: probes.csv's rows at the time reached, (time, name, "
                             "head, pressure)")
      .def("run_pass", &Simulation::run_pass, "Coupled: one coupling pass; what it measured, as a dict.")
      .def_property_readonly("finished", &Simulation::finished,
                             "steps or end_time reached; coupling converged; flow solved")
      .def_property_readonly("fluid", &Simulation::fluid)
      .def_property_readonly("blocks", &Simulation::blocks)
      .def_property_readonly("contacts", &Simulation::contacts)
      .def_property_readonly("fractures", &Simulation::fractures,
                             "Per fracture, as fractures.csv's columns (a dict of arrays); None without a [geometry] domain")
      .def_property_readonly("broken_bonds", &Simulation::broken_bonds,
                             "Coupled transient: the bonds broken so far, by time step, as fractures.csv's bond rows "
                             "(a dict of arrays)")
      .def("set", &Simulation::set, py::arg("key"), py::arg("value"),
           "Changes a flow boundary's head, pressure or flux, or a traction, from the next step or pass on.")
      .def_property_readonly("scenario", &Simulation::scenario, "The scenario as built, with the changes set() made")
      .def_property_readonly("summary", &Simulation::summary, "summary.json's content for the state now (no timings)");
}

}  // namespace hydrodda::python
