// The run layer logs through spdlog's default logger and leaves its configuration to the front
// end. In Python the front end is the `logging` module: every message goes to the logger
// "hydrodda" at the matching level, so warnings show by default and informational lines when
// the user asks (logging.basicConfig(level=logging.INFO)).

#include <spdlog/details/null_mutex.h>
#include <spdlog/sinks/base_sink.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <string>

#include "python/bindings.hpp"
#include "python/python_callbacks.hpp"

namespace hydrodda::python {

namespace {

int python_level(spdlog::level::level_enum level) {
  switch (level) {
    case spdlog::level::trace:
    case spdlog::level::debug: return 10;  // logging.DEBUG
    case spdlog::level::info: return 20;
    case spdlog::level::warn: return 30;
    case spdlog::level::err: return 40;
    default: return 50;
  }
}

// A handler that fails (an Exception) must not fail the run: it is dropped. Ctrl-C while the
// handler runs raises KeyboardInterrupt in it, and SystemExit may be raised there too: those
// stop the run under way on this thread, as Ctrl-C between steps does, and are raised once it
// has stopped. Without a run under way on this thread, Ctrl-C on the main thread is raised at
// Python's next check for signals.
void keep_interrupt(py::error_already_set&& error) {
  if (error.matches(PyExc_Exception)) return;
  const bool interrupt = error.matches(PyExc_KeyboardInterrupt);
  if (PythonCallbacks::take_interrupt(std::move(error))) return;
  if (!interrupt) return;
  const py::module_ threading = py::module_::import("threading");
  if (threading.attr("current_thread")().is(threading.attr("main_thread")())) PyErr_SetInterrupt();
}

// Not spdlog's lock but the GIL orders the messages: a thread in the sink waiting for the GIL
// while holding a lock would block a thread that holds the GIL and logs (Scenario.load's
// warnings beside another thread's run).
class PythonLoggingSink : public spdlog::sinks::base_sink<spdlog::details::null_mutex> {
 protected:
  void sink_it_(const spdlog::details::log_msg& message) override {
    if (!Py_IsInitialized()) return;
    const std::string text(message.payload.data(), message.payload.size());
    // Runs release the GIL; a message from inside one takes it back.
    py::gil_scoped_acquire gil;
    try {
      py::module_::import("logging").attr("getLogger")("hydrodda").attr("log")(python_level(message.level), text);
    } catch (py::error_already_set& error) {
      keep_interrupt(std::move(error));
    }
  }
  void flush_() override {}
};

}  // namespace

void route_logging_to_python() {
  auto logger = std::make_shared<spdlog::logger>("hydrodda", std::make_shared<PythonLoggingSink>());
  logger->set_level(spdlog::level::debug);  // Python's logging filters
  spdlog::set_default_logger(logger);
}

}  // namespace hydrodda::python
