// The extension module _hydrodda, wrapped by the package python/hydrodda/.

#include "numerics/blas_threads.hpp"
#include "python/bindings.hpp"

PYBIND11_MODULE(_hydrodda, module) {
  namespace python = hydrodda::python;
  module.doc() = "hydrodda's run layer: scenarios, runs and their fields";
  module.attr("__version__") = HYDRODDA_VERSION;
  python::bind_errors(module);
  python::bind_scenario(module);
  python::bind_run(module);
  python::bind_simulation(module);
  python::route_logging_to_python();
  // For the tests: whether OpenBLAS's calls reach the module's lock (numerics/blas_threads.hpp).
  module.def("_blas_is_thread_safe", &hydrodda::numerics::blas_is_thread_safe);
}
