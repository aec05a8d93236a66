#pragma once
// The checkpoint of a coupled run (checkpoint.bin in the run folder): everything needed to
// continue the run after its last finished coupling iteration and reach the same results, bit
// for bit, as a run that was never stopped. No wall-clock timings: two identical runs write
// identical checkpoints (a resumed run's summary.json times its own part only).
//
// Format: the magic line "hydrodda checkpoint\n", a format version, a byte-order mark, then
// the fields below in order; numbers as raw 8-byte integers and IEEE doubles in the writing
// machine's byte order (a checkpoint is read back where it was written, not exchanged), strings
// and lists prefixed with their length; last, the CRC-32 of all the bytes before it (as a
// 64-bit word). A file of another version or byte order, or a cut or damaged one (any byte changed), is
// refused with CheckpointError.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "coupling/staggered_loop.hpp"
#include "dda/system.hpp"
#include "hydro/flow_solution.hpp"
#include "output/atomic_file.hpp"

namespace hydrodda::output {

// A file the scenario names, as the run read it at its start.
struct InputFile {
  std::string key;          // the scenario key that names it: geometry.fractures_file, mesh.file
  std::string path;         // absolute
  std::uint64_t hash = 0;   // hash_text() of its content
};

struct RunCheckpoint {
  std::uint64_t scenario_hash = 0;  // hash_text() of the scenario text the run started from
  std::string scenario_file;        // that scenario's absolute path (base of its relative paths)
  std::vector<InputFile> input_files;  // every file the scenario names: a resumed run reads the same
  bool converged = false;
  std::vector<std::vector<std::string>> history;  // history.csv rows so far, header excluded
  std::vector<std::vector<std::string>> measure;  // measure.csv rows so far, header excluded
  std::vector<int> written_iterations;            // iterations whose ParaView files exist
  // The wedge tips the run has refined the mesh around (mesh.refine_tips), five numbers each:
  // x, y, size, radius and the round that found them; a resumed run meshes with them before it
  // takes up the engines' states.
  std::vector<double> refined_tips;
  // The tips unresolved in the round's last passes (a round that does not converge refines them
  // all): each pass as its iteration, its tip count, then five numbers a tip as above.
  std::vector<double> recent_tips;
  dda::SystemState mechanics;
  coupling::LoopState coupling;
};

std::string encode_checkpoint(const RunCheckpoint& checkpoint);
// The same bytes with the engines' states given apart (checkpoint.mechanics and .coupling are
// not read): a run encodes the states it holds without copying them into a RunCheckpoint.
std::string encode_checkpoint(const RunCheckpoint& checkpoint, const dda::SystemState& mechanics,
                              const coupling::LoopState& coupling);
// The same bytes written into `file` as they are encoded, a megabyte at a time; the caller
// commits the file.
void write_checkpoint(AtomicFile& file, const RunCheckpoint& checkpoint, const dda::SystemState& mechanics,
                      const coupling::LoopState& coupling);
// Throws CheckpointError when the bytes are not a whole checkpoint of this format.
RunCheckpoint decode_checkpoint(std::string_view bytes);

// The checkpoint of a transient flow-only run ([flow.transient]), in the same file
// (checkpoint.bin), written at each output time and when the run is interrupted: the state after
// its last finished step and what its files and figures hold so far, so that a resumed run
// continues bit for bit. Format as above, under its own magic line "hydrodda transient
// checkpoint\n" and version.
struct TransientCheckpoint {
  std::uint64_t scenario_hash = 0;
  std::string scenario_file;
  std::vector<InputFile> input_files;
  int steps = 0;           // steps of the plan finished (run::plan_step_times)
  double time = 0.0;       // their end (s)
  double time_step = 0.0;  // the last one's length (s); 0 at t = 0
  std::vector<std::vector<std::string>> history;  // history.csv rows so far, header excluded
  std::vector<std::vector<std::string>> probes;   // probes.csv rows so far, header excluded
  std::vector<double> output_times;               // fluid_NNNN.vtu written, NNNN the index
  // The figures' series so far: each recorded time, the rate of storage, each mesh boundary's
  // outward flow and each probe's pressure then.
  std::vector<double> times, storage_rates;
  std::vector<std::vector<double>> boundary_flows, probe_pressures;
  hydro::FlowSolution state;  // head, pressure, flux, boundary flows, balance, storage rate
};

std::string encode_transient_checkpoint(const TransientCheckpoint& checkpoint);
// Throws CheckpointError when the bytes are not a whole transient checkpoint of this format.
TransientCheckpoint decode_transient_checkpoint(std::string_view bytes);
// The bytes begin as a transient run's checkpoint does (which of the two to decode).
bool is_transient_checkpoint(std::string_view bytes);

// The checkpoint of a coupled transient run ([mechanics] with [flow.transient]), in the same file
// (checkpoint.bin), written at t = 0, at each output time, when the run is interrupted and at
// its end: the state after its last finished step, where its step control stands, and what its
// files and figures hold so far, so that a resumed run continues bit for bit. Format as above,
// under its own magic line "hydrodda coupled transient checkpoint\n" and version.
struct CoupledTransientCheckpoint {
  std::uint64_t scenario_hash = 0;
  std::string scenario_file;
  std::vector<InputFile> input_files;
  // The run ended: it reached end_time, or a step failed at the floor (nothing to resume).
  bool ended = false;
  // The step control (run::StepPosition): steps taken, the time they reached, the nominal length
  // of the next step and the index of the next stop it lands on (run::find_step_stops).
  int steps = 0;
  double time = 0.0;
  double nominal_step = 0.0;
  int next_stop = 0;
  std::vector<std::vector<std::string>> history;  // history.csv rows so far, header excluded
  std::vector<std::vector<std::string>> probes;   // probes.csv rows so far
  std::vector<std::vector<std::string>> measure;  // measure.csv rows so far
  std::vector<double> output_times;  // the times of the fields_NNNN.vtu written, NNNN the index
  // The figures' series so far: each step's time, rate of storage, each [[flow.boundary]]'s
  // outward flow and each probe's pressure then, and with fractures five numbers a step
  // (open, partly open, open length, largest opening, largest hydraulic aperture).
  std::vector<double> times, storage_rates;
  std::vector<std::vector<double>> boundary_flows, probe_pressures;
  std::vector<double> fracture_counts;
  dda::SystemState mechanics;
  coupling::LoopState coupling;  // its flow's storage_rate included
};

std::string encode_coupled_transient_checkpoint(const CoupledTransientCheckpoint& checkpoint);
// The same bytes with the engines' states given apart (checkpoint.mechanics and .coupling are
// not read).
std::string encode_coupled_transient_checkpoint(const CoupledTransientCheckpoint& checkpoint,
                                                const dda::SystemState& mechanics, const coupling::LoopState& coupling);
// Throws CheckpointError when the bytes are not a whole coupled transient checkpoint of this
// format (one of an older format says which it is and which this hydrodda reads).
CoupledTransientCheckpoint decode_coupled_transient_checkpoint(std::string_view bytes);
bool is_coupled_transient_checkpoint(std::string_view bytes);

// 64-bit FNV-1a of a text: tells a scenario edited since the run started.
std::uint64_t hash_text(std::string_view text);

class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hydrodda::output
