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
  explicit PythonCallbacks(py::object progress) : progress_(std::move(progress)) {}

  // Valid while this object lives; call the run with the GIL released.
  run::Callbacks callbacks();
  // Raises the pending Python error, if any (with the GIL held).
  void raise_pending();

 private:
  py::object progress_;
  std::optional<py::error_already_set> pending_;
};

}  // namespace hydrodda::python
