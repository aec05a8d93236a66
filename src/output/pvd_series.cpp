#include "output/pvd_series.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "output/atomic_file.hpp"
#include "output/vtk_writer.hpp"

namespace hydrodda::output {

PvdSeries::PvdSeries(std::filesystem::path pvd_file) : path_(std::move(pvd_file)) {}

void PvdSeries::add(double time, const std::string& relative_vtu, int part) {
  if (!std::isfinite(time)) {
    throw std::invalid_argument(
        fmt::format("PVD series {}: non-finite time for '{}'", path_.string(), relative_vtu));
  }
  if (relative_vtu.empty()) {
    throw std::invalid_argument(fmt::format("PVD series {}: empty data set file name",
                                            path_.string()));
  }
  entries_.push_back({time, relative_vtu, part});
  write_file_atomically(path_, text(), Durability::atomic);  // a run's index of fields: RunFolder::durability_of
}

std::string PvdSeries::text() const {
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (const Entry& e : entries_) {
    // Full precision so a time read back equals the simulation time.
    fmt::format_to(std::back_inserter(out),
                   "    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"{}\" file=\"{}\"/>\n",
                   e.time, e.part, escape_xml(e.file));
  }
  out += "  </Collection>\n";
  out += "</VTKFile>\n";
  return out;
}

}  // namespace hydrodda::output
