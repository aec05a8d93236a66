#!/usr/bin/env bash
# Installs the Debian packages hydrodda needs to build, test and run.
# Does nothing when every package is already present. Debian 12 (bookworm), run as root.
set -euo pipefail

build_packages=(
  build-essential cmake pkg-config
  libeigen3-dev            # dense and sparse linear algebra
  libsuitesparse-dev       # CHOLMOD sparse Cholesky
  libmetis-dev             # graph ordering for CHOLMOD
  libblas-dev liblapack-dev  # dense kernels of the flow's own supernodal factorisation
  # OpenBLAS for CHOLMOD's dense kernels in place of the reference BLAS, which Debian's
  # alternatives then point libblas.so.3 and liblapack.so.3 at: a flow factorisation of 10^6
  # triangles 2.1-2.3 s -> 1.2-1.3 s. The serial build: one thread, so every result is the same
  # on one core or two, whatever the program's own thread count.
  libopenblas0-serial
  libgmsh-dev gmsh         # meshing (C++ API)
  libtomlplusplus-dev      # scenario files
  libcli11-dev             # command line
  libfmt-dev libspdlog-dev # text and logs
  nlohmann-json3-dev       # summary.json
  libcairo2-dev            # figures
  zlib1g-dev               # compressed arrays of the ParaView (.vtu) files
  libjemalloc-dev          # memory allocator, on transparent huge pages
  libgtest-dev libgmock-dev libbenchmark-dev
  libboost-dev             # Boost.Geometry: test oracle for clipping
  # Reading our VTU/PVD back in tests: VTK's XML reader from python3 and ParaView's own reader
  # under pvbatch (headless through xvfb-run). python3-paraview brings VTK's Python modules
  # (vtkmodules) and conflicts with python3-vtk9, which provides the same modules alone.
  python3 paraview python3-paraview xvfb xauth
  python3-dev pybind11-dev # the Python module (src/python/)
  python3-numpy            # its fields and histories as arrays
  python3-pytest           # its tests (tests/python/)
  python3-matplotlib       # its examples (examples/python/), with the Agg backend
  clang libclang-rt-14-dev # libFuzzer for the scenario reader
  # Open MPI: `mpirun hydrodda sweep` spreads a sweep's cases over ranks on one host or many
  # (optional in CMake; the MPI sweep test needs mpirun from openmpi-bin)
  libopenmpi-dev openmpi-bin
)

missing=()
for pkg in "${build_packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}" >&2
  echo "install-deps: run as root (or install them with apt-get) and try again" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
