# The Python module (src/python/): pybind11 (pybind11-dev) for the interpreter's development
# files (python3-dev). Without them the module is left out with a note, and its tests with it.
include(GNUInstallDirs)
if(HYDRODDA_PYTHON)
  # Debian's python3, whose packages (python3-numpy, python3-pytest) install-deps.sh installs,
  # rather than another interpreter first on PATH.
  if(NOT Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the module is built for")
  endif()
  find_package(Python3 COMPONENTS Interpreter Development.Module)
  find_package(pybind11 CONFIG QUIET)
  if(NOT Python3_FOUND OR NOT pybind11_FOUND)
    message(STATUS "Python module: off (install python3-dev and pybind11-dev)")
    set(HYDRODDA_PYTHON OFF)
  else()
    # The module links the static libraries into a shared object: their code must be
    # position-independent.
    set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  endif()
endif()
