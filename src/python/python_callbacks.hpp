#pragma once
// The run layer's callbacks for a run that Python started and that runs with the GIL released:
// the progress callback in Python, and a stop request when Ctrl-C (or any Python error, such as
// one raised in the progress callback) is pending. The error is raised again once the run has
// stopped cleanly, its run folder at the last finished step or pass.

#include <optional>

#include "python/bindings.hpp"
#include "run/run.hpp"

namespace hydrodda::python {

class PythonCallbacks {
 public:
  // `keep_fields`: keep the model's fields at the run's end (fields_at_end). Make it on the
  // thread that runs, and keep it there until the run is over: while it lives it is the one
  // take_interrupt() hands to.
  explicit PythonCallbacks(py::object progress, bool keep_fields = false);
  ~PythonCallbacks();
  PythonCallbacks(const PythonCallbacks&) = delete;
  PythonCallbacks& operator=(const PythonCallbacks&) = delete;

  // An error that must stop the run rather than be dropped (KeyboardInterrupt raised in a
  // logging handler while the run logged): kept by the calling thread's run, which then stops
  // as at Ctrl-C and raises it. False when no run is under way on this thread.
  static bool take_interrupt(py::error_already_set&& error);

  // Valid while this object lives; call the run with the GIL released.
  run::Callbacks callbacks();
  // Raises the pending Python error, if any (with the GIL held).
  void raise_pending();
  // The model's fields as the run ended (model_fields.hpp: fields_at_end); an empty dict when
  // the run built no model.
  py::dict fields_at_end() const { return fields_at_end_ ? *fields_at_end_ : py::dict(); }

 private:
  py::object progress_;
  bool keep_fields_ = false;
  std::optional<py::error_already_set> pending_;
  std::optional<py::dict> fields_at_end_;
  PythonCallbacks* enclosing_;  // the run under way on this thread before this one, if any
};

}  // namespace hydrodda::python
