// The run layer logs through spdlog's default logger and leaves its configuration to the front
// end. In Python the front end is the `logging` module: every message goes to the logger
// "hydrodda" at the matching level, so warnings show by default and informational lines when
// the user asks (logging.basicConfig(level=logging.INFO)).

#include <spdlog/sinks/base_sink.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <mutex>
#include <string>

#include "python/bindings.hpp"

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

class PythonLoggingSink : public spdlog::sinks::base_sink<std::mutex> {
 protected:
  void sink_it_(const spdlog::details::log_msg& message) override {
    if (!Py_IsInitialized()) return;
    const std::string text(message.payload.data(), message.payload.size());
    // Runs release the GIL; a message from inside one takes it back.
    py::gil_scoped_acquire gil;
    try {
      py::module_::import("logging").attr("getLogger")("hydrodda").attr("log")(python_level(message.level), text);
    } catch (py::error_already_set&) {
      PyErr_Clear();  // a logging handler that fails must not fail the run
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
