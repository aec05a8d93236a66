#include "output/checkpoint.hpp"

#include <algorithm>
#include <cstring>
#include <functional>
#include <memory>
#include <span>
#include <type_traits>
#include <utility>

#include "output/zlib_blocks.hpp"

namespace hydrodda::output {

namespace {

constexpr std::string_view kMagic = "hydrodda checkpoint\n";
// 2: measure.csv rows after history.csv's; 3: the coupling loop's Aitken state; 4: a checksum
// and no timings (so that identical runs write identical checkpoints); 5: the flow solver's kept
// factor (its permeability) at the end; 6: Anderson's history; 7: the kept factor's
// permeability as tensors (xx, xy, yy), joint apertures' included; 8: CRC-32 in place of FNV-1a
// as the checksum; 11: the wedge tips of mesh.refine_tips (refined, and of the round's last
// passes); 13: the hashes of the files the scenario names, and the porosity and permeability
// of the last pass; 14: history rows end in each pass's changes (contacts, joint crossings,
// fluid load, open–close iterations, step cuts); 15: whether the tension cutoff released each
// open contact; 16: the bonds broken so far (a resumed run had its sub-blocks bonded whole
// again); 17: the bonds softening, with their faces' peak openings; 18: the float secant's memory
// of the groups free in the last pass. Only the current format is read: a run stopped by an
// older hydrodda is run again.
constexpr std::int64_t kVersion = 19;
// The last 8 bytes: the CRC-32 of every byte before them (zlib's, as a 64-bit word). A CRC
// detects every error burst of up to 32 bits, so a flipped bit is refused, not resumed from;
// zlib computes it four times as fast as a byte-at-a-time hash on a checkpoint of tens of MB.
constexpr std::size_t kChecksumSize = sizeof(std::uint64_t);
std::uint64_t checksum_of(std::string_view bytes) { return crc32_of(std::as_bytes(std::span(bytes))); }
constexpr std::uint32_t kByteOrderMark = 0x01020304;
// Any list longer than the file could hold is damage, not data; this bounds allocations.
constexpr std::int64_t kMaxCount = std::int64_t{1} << 40;

using geometry::Point;

// Writes the bytes in pieces of about kPiece to a sink, with their running CRC-32: a checkpoint
// of a million-triangle run is tens of megabytes, never held whole in memory.
class Writer {
 public:
  using Sink = std::function<void(std::string_view)>;
  explicit Writer(Sink sink) : sink_(std::move(sink)) { buffer_.reserve(kPiece + 64); }

  template <class T>
  void put_raw(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    append({bytes, sizeof(T)});
  }
  void put(std::int64_t v) { put_raw(v); }
  void put(int v) { put_raw(static_cast<std::int64_t>(v)); }
  void put(bool v) { put_raw(static_cast<std::int64_t>(v)); }
  void put(double v) { put_raw(v); }
  void put(std::uint64_t v) { put_raw(v); }
  void put(const std::string& s) {
    put(static_cast<std::int64_t>(s.size()));
    append(s);
  }
  void put(Point p) {
    put(p.x);
    put(p.y);
  }
  void put(const hydro::PermeabilityTensor& k) {
    put(k.xx);
    put(k.xy);
    put(k.yy);
  }
  // Written as the list of tensors it stands for (an isotropic k as {k, 0, k}; none: empty),
  // a few thousand at a time rather than copied whole.
  void put(const std::shared_ptr<const hydro::PermeabilityField>& field) {
    const std::size_t n = field ? field->size() : 0;
    put(static_cast<std::int64_t>(n));
    std::vector<hydro::PermeabilityTensor> chunk;
    for (std::size_t first = 0; first < n; first += kTensorsAtATime) {
      chunk.clear();
      for (std::size_t e = first; e < std::min(n, first + kTensorsAtATime); ++e) chunk.push_back(field->view()[e]);
      if constexpr (kStoredAsInMemory<hydro::PermeabilityTensor>) {
        append({reinterpret_cast<const char*>(chunk.data()), chunk.size() * sizeof(hydro::PermeabilityTensor)});
      } else {
        for (const hydro::PermeabilityTensor& k : chunk) put(k);
      }
    }
  }
  template <class T, std::size_t N>
  void put(const std::array<T, N>& a) {
    for (const T& v : a) put(v);
  }
  template <class T>
  void put(const std::vector<T>& list) {
    put(static_cast<std::int64_t>(list.size()));
    if constexpr (kStoredAsInMemory<T>) {
      append({reinterpret_cast<const char*>(list.data()), list.size() * sizeof(T)});  // one copy, not one per number
    } else {
      for (const T& v : list) put(v);
    }
  }
  // The bytes so far to the sink, then their checksum (kChecksumSize bytes) after them.
  void finish() {
    flush();
    const std::uint64_t checksum = crc_;
    char sum[kChecksumSize];
    std::memcpy(sum, &checksum, kChecksumSize);
    sink_({sum, kChecksumSize});
  }

 private:
  static constexpr std::size_t kPiece = std::size_t{1} << 20;
  static constexpr std::size_t kTensorsAtATime = 4096;
  // Types whose put() writes exactly their bytes in memory (8-byte numbers, no padding), so a
  // list of them is written in one piece.
  template <class T>
  static constexpr bool kStoredAsInMemory =
      std::is_same_v<T, double> || std::is_same_v<T, std::int64_t> ||
      (std::is_same_v<T, Point> && sizeof(Point) == 2 * sizeof(double)) ||
      (std::is_same_v<T, hydro::PermeabilityTensor> && sizeof(hydro::PermeabilityTensor) == 3 * sizeof(double));
  void append(std::string_view bytes) {
    if (bytes.size() >= kPiece) {  // a long list goes out as it is, after what came before it
      flush();
      send(bytes);
      return;
    }
    buffer_ += bytes;
    if (buffer_.size() >= kPiece) flush();
  }
  void flush() {
    send(buffer_);
    buffer_.clear();
  }
  void send(std::string_view bytes) {
    crc_ = crc32_of(std::as_bytes(std::span(bytes)), crc_);
    sink_(bytes);
  }

  Sink sink_;
  std::string buffer_;
  std::uint32_t crc_ = 0;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : in_(bytes) {}

  template <class T>
  T get_raw() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T value;
    std::memcpy(&value, in_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  void get(std::int64_t& v) { v = get_raw<std::int64_t>(); }
  void get(std::uint64_t& v) { v = get_raw<std::uint64_t>(); }
  void get(double& v) { v = get_raw<double>(); }
  void get(int& v) {
    const std::int64_t wide = get_raw<std::int64_t>();
    if (wide < INT32_MIN || wide > INT32_MAX) fail();
    v = static_cast<int>(wide);
  }
  void get(bool& v) {
    const std::int64_t wide = get_raw<std::int64_t>();
    if (wide != 0 && wide != 1) fail();
    v = wide == 1;
  }
  void get(std::string& s) {
    const std::size_t n = get_count();
    need(n);
    s.assign(in_.data() + at_, n);
    at_ += n;
  }
  void get(Point& p) {
    get(p.x);
    get(p.y);
  }
  void get(hydro::PermeabilityTensor& k) {
    get(k.xx);
    get(k.xy);
    get(k.yy);
  }
  template <class T, std::size_t N>
  void get(std::array<T, N>& a) {
    for (T& v : a) get(v);
  }
  template <class T>
  void get(std::vector<T>& list) {
    const std::size_t n = get_count();
    list.clear();
    for (std::size_t i = 0; i < n; ++i) {
      T v{};
      get(v);
      list.push_back(std::move(v));
    }
  }
  void expect(std::string_view text) {
    need(text.size());
    if (in_.substr(at_, text.size()) != text) fail();
    at_ += text.size();
  }
  void expect_end() const {
    if (at_ != in_.size()) fail();
  }
  [[noreturn]] void fail() const { throw CheckpointError("the checkpoint is damaged or cut short"); }

 private:
  std::size_t get_count() {
    const auto n = get_raw<std::int64_t>();
    if (n < 0 || n > kMaxCount || static_cast<std::size_t>(n) > in_.size() - at_) fail();
    return static_cast<std::size_t>(n);
  }
  void need(std::size_t n) const {
    if (n > in_.size() - at_) fail();
  }

  std::string_view in_;
  std::size_t at_ = 0;
};

// The DDA and loop records, field by field, in one order for writing and reading.
template <class Io, class Record>
void visit_record(Io&& io, Record& r) {
  int state = static_cast<int>(r.state);
  io(state);
  r.state = static_cast<dda::ContactState>(state);
  io(r.reference_ratio);
  io(r.multiplier);
  io(r.slide_sign);
  io(r.normal_force);
  io(r.penetration);
  bool released = r.released;
  io(released);
  r.released = released;
}

void write_mechanics(Writer& w, const dda::SystemState& s) {
  w.put(static_cast<std::int64_t>(s.blocks.size()));
  for (const dda::SystemState::BlockState& b : s.blocks) {
    w.put(b.polygon);
    w.put(b.velocity);
    w.put(b.stress);
    w.put(b.strain);
    w.put(b.rotation);
    w.put(b.material_centroid);
  }
  w.put(s.time);
  w.put(s.time_step);
  w.put(static_cast<std::int64_t>(s.contacts.size()));
  for (const auto& [key, record] : s.contacts) {
    for (int v : {key.block_i, key.vertex, key.block_j, key.edge}) w.put(v);
    dda::ContactRecord r = record;
    visit_record([&](auto& v) { w.put(v); }, r);
  }
  w.put(s.fixed_points);
  w.put(s.load_points);
  w.put(s.displacement_points);
  w.put(s.measured_points);
  w.put(s.vertex_forces);
  w.put(s.roller_reliefs);
  w.put(static_cast<std::int64_t>(s.bond_breaks.size()));
  for (const dda::BondBreak& b : s.bond_breaks) {
    w.put(b.bond);
    w.put(b.time);
    w.put(static_cast<int>(b.mode));
    w.put(b.from);
    w.put(b.to);
  }
  w.put(static_cast<std::int64_t>(s.softening_bonds.size()));
  for (const dda::SofteningBond& b : s.softening_bonds) {
    w.put(b.bond);
    w.put(b.peak_opening[0]);
    w.put(b.peak_opening[1]);
  }
}

void read_mechanics(Reader& r, dda::SystemState& s) {
  std::int64_t blocks = 0;
  r.get(blocks);
  if (blocks < 0 || blocks > kMaxCount) r.fail();
  for (std::int64_t i = 0; i < blocks; ++i) {
    dda::SystemState::BlockState b;
    r.get(b.polygon);
    r.get(b.velocity);
    r.get(b.stress);
    r.get(b.strain);
    r.get(b.rotation);
    r.get(b.material_centroid);
    s.blocks.push_back(std::move(b));
  }
  r.get(s.time);
  r.get(s.time_step);
  std::int64_t contacts = 0;
  r.get(contacts);
  if (contacts < 0 || contacts > kMaxCount) r.fail();
  for (std::int64_t i = 0; i < contacts; ++i) {
    dda::ContactKey key;
    r.get(key.block_i);
    r.get(key.vertex);
    r.get(key.block_j);
    r.get(key.edge);
    dda::ContactRecord record;
    visit_record([&](auto& v) { r.get(v); }, record);
    if (static_cast<int>(record.state) < 0 || static_cast<int>(record.state) > 2) r.fail();
    s.contacts.emplace_back(key, record);
  }
  r.get(s.fixed_points);
  r.get(s.load_points);
  r.get(s.displacement_points);
  r.get(s.measured_points);
  r.get(s.vertex_forces);
  r.get(s.roller_reliefs);
  std::int64_t breaks = 0;
  r.get(breaks);
  if (breaks < 0 || breaks > kMaxCount) r.fail();
  for (std::int64_t i = 0; i < breaks; ++i) {
    dda::BondBreak b;
    r.get(b.bond);
    r.get(b.time);
    int mode = 0;
    r.get(mode);
    if (mode < static_cast<int>(dda::BondFailure::tension) || mode > static_cast<int>(dda::BondFailure::shear)) r.fail();
    b.mode = static_cast<dda::BondFailure>(mode);
    r.get(b.from);
    r.get(b.to);
    s.bond_breaks.push_back(b);
  }
  std::int64_t softening = 0;
  r.get(softening);
  if (softening < 0 || softening > kMaxCount) r.fail();
  for (std::int64_t i = 0; i < softening; ++i) {
    dda::SofteningBond b;
    r.get(b.bond);
    r.get(b.peak_opening[0]);
    r.get(b.peak_opening[1]);
    s.softening_bonds.push_back(b);
  }
}

// `Flow`: a hydro::FlowSolution, const when written.
template <class Io, class Flow>
void visit_flow(Io&& io, Flow& f) {
  io(f.head);
  io(f.pressure);
  io(f.flux);
  io(f.reference_head);
  io(f.balance_error);
  io(f.refinement_steps);
}

// A reader after the header of a checkpoint file of the given magic and format, once its
// format, length, checksum and byte order are checked (CheckpointError naming what failed).
Reader open_checked(std::string_view file, std::string_view magic, std::int64_t version, const std::string& what) {
  {
    Reader header(file);
    header.expect(magic);
    std::int64_t found = 0;
    header.get(found);
    if (found != version)
      throw CheckpointError(what + " format " + std::to_string(found) + "; this hydrodda reads format " +
                            std::to_string(version));
  }
  if (file.size() < magic.size() + kChecksumSize) throw CheckpointError("the checkpoint is damaged or cut short");
  const std::string_view bytes = file.substr(0, file.size() - kChecksumSize);
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, file.data() + bytes.size(), kChecksumSize);
  if (checksum != checksum_of(bytes))
    throw CheckpointError("the checkpoint is damaged or cut short: its checksum does not match its contents");
  Reader r(bytes);
  r.expect(magic);
  std::int64_t found = 0;
  r.get(found);
  if (r.get_raw<std::uint32_t>() != kByteOrderMark)
    throw CheckpointError("the checkpoint was written on a machine of another byte order");
  return r;
}

void get_input_files(Reader& r, std::vector<InputFile>& files) {
  std::int64_t count = 0;
  r.get(count);
  if (count < 0 || count > kMaxCount) r.fail();
  for (std::int64_t i = 0; i < count; ++i) {
    InputFile f;
    r.get(f.key);
    r.get(f.path);
    r.get(f.hash);
    files.push_back(std::move(f));
  }
}

// The coupling loop's state (LoopState), in one order for both checkpoints.
void write_loop_state(Writer& w, const coupling::LoopState& coupling) {
  w.put(coupling.iterations);
  const hydro::FlowSolution& flow = coupling.flow;
  visit_flow([&](const auto& v) { w.put(v); }, flow);
  w.put(static_cast<std::int64_t>(flow.boundary_flows.size()));
  for (const hydro::BoundaryFlow& b : flow.boundary_flows) {
    w.put(b.name);
    w.put(b.flow);
  }
  w.put(coupling.previous_heads);
  w.put(coupling.previous_displacements);
  w.put(coupling.growth.passes);
  w.put(coupling.growth.base);
  w.put(coupling.growth.last);
  w.put(coupling.heads_two_back);
  w.put(coupling.previous_update);
  w.put(coupling.relaxation);
  w.put(coupling.anderson_residuals);
  w.put(coupling.anderson_images);
  w.put(coupling.kept_factor_permeability);
  w.put(static_cast<std::int64_t>(coupling.kept_factor_single_precision));
  w.put(coupling.porosity.fracture_area);
  w.put(coupling.porosity.porosity);
  w.put(coupling.permeability);
  w.put(coupling.permeability_tensors);
  std::vector<std::vector<int>> groups;
  std::vector<Point> starts, rates;
  for (const coupling::FloatSecant::Remembered& g : coupling.float_groups) {
    groups.push_back(g.group);
    starts.push_back(g.start);
    rates.push_back(g.rate);
  }
  w.put(groups);
  w.put(starts);
  w.put(rates);
  w.put(static_cast<std::int64_t>(coupling.ramp_passes));
}

void read_loop_state(Reader& r, coupling::LoopState& s) {
  r.get(s.iterations);
  visit_flow([&](auto& v) { r.get(v); }, s.flow);
  std::int64_t boundaries = 0;
  r.get(boundaries);
  if (boundaries < 0 || boundaries > kMaxCount) r.fail();
  for (std::int64_t i = 0; i < boundaries; ++i) {
    hydro::BoundaryFlow b;
    r.get(b.name);
    r.get(b.flow);
    s.flow.boundary_flows.push_back(std::move(b));
  }
  r.get(s.previous_heads);
  r.get(s.previous_displacements);
  r.get(s.growth.passes);
  r.get(s.growth.base);
  r.get(s.growth.last);
  r.get(s.heads_two_back);
  r.get(s.previous_update);
  r.get(s.relaxation);
  r.get(s.anderson_residuals);
  r.get(s.anderson_images);
  std::vector<hydro::PermeabilityTensor> kept;
  r.get(kept);
  if (!kept.empty()) s.kept_factor_permeability = std::make_shared<const hydro::PermeabilityField>(kept);
  std::int64_t single_precision = 0;
  r.get(single_precision);
  if (single_precision != 0 && single_precision != 1) r.fail();
  s.kept_factor_single_precision = single_precision == 1;
  r.get(s.porosity.fracture_area);
  r.get(s.porosity.porosity);
  r.get(s.permeability);
  r.get(s.permeability_tensors);
  std::vector<std::vector<int>> groups;
  std::vector<Point> starts, rates;
  r.get(groups);
  r.get(starts);
  r.get(rates);
  if (starts.size() != groups.size() || rates.size() != groups.size()) r.fail();
  for (std::size_t g = 0; g < groups.size(); ++g) s.float_groups.push_back({std::move(groups[g]), starts[g], rates[g]});
  std::int64_t ramp_passes = 0;
  r.get(ramp_passes);
  if (ramp_passes < 1 || ramp_passes > 1'000'000) r.fail();
  s.ramp_passes = static_cast<int>(ramp_passes);
}

}  // namespace

std::uint64_t hash_text(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a offset basis and prime
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string encode_checkpoint(const RunCheckpoint& c) { return encode_checkpoint(c, c.mechanics, c.coupling); }

namespace {
void put_checkpoint(Writer& w, const RunCheckpoint& c, const dda::SystemState& mechanics,
                    const coupling::LoopState& coupling) {
  for (char ch : kMagic) w.put_raw(ch);
  w.put(kVersion);
  w.put_raw(kByteOrderMark);
  w.put(c.scenario_hash);
  w.put(c.scenario_file);
  w.put(static_cast<std::int64_t>(c.input_files.size()));
  for (const InputFile& f : c.input_files) {
    w.put(f.key);
    w.put(f.path);
    w.put(f.hash);
  }
  w.put(c.converged);
  w.put(c.history);
  w.put(c.measure);
  w.put(c.written_iterations);
  w.put(c.refined_tips);
  w.put(c.recent_tips);
  write_mechanics(w, mechanics);
  write_loop_state(w, coupling);
  w.finish();
}
}  // namespace

std::string encode_checkpoint(const RunCheckpoint& c, const dda::SystemState& mechanics,
                              const coupling::LoopState& coupling) {
  std::string bytes;
  Writer w([&](std::string_view piece) { bytes += piece; });
  put_checkpoint(w, c, mechanics, coupling);
  return bytes;
}

void write_checkpoint(AtomicFile& file, const RunCheckpoint& c, const dda::SystemState& mechanics,
                      const coupling::LoopState& coupling) {
  Writer w([&](std::string_view piece) { file.write(piece); });
  put_checkpoint(w, c, mechanics, coupling);
}

RunCheckpoint decode_checkpoint(std::string_view file) {
  if (file.substr(0, kMagic.size()) != kMagic) throw CheckpointError("not a hydrodda checkpoint");
  Reader r = open_checked(file, kMagic, kVersion, "checkpoint");
  RunCheckpoint c;
  r.get(c.scenario_hash);
  r.get(c.scenario_file);
  get_input_files(r, c.input_files);
  r.get(c.converged);
  r.get(c.history);
  r.get(c.measure);
  r.get(c.written_iterations);
  r.get(c.refined_tips);
  if (c.refined_tips.size() % 5 != 0) r.fail();
  r.get(c.recent_tips);
  read_mechanics(r, c.mechanics);
  read_loop_state(r, c.coupling);
  r.expect_end();
  return c;
}

}  // namespace hydrodda::output

// The transient run's checkpoint: its own magic line and version, the Writer and Reader above.
namespace hydrodda::output {

namespace {

constexpr std::string_view kTransientMagic = "hydrodda transient checkpoint\n";
constexpr std::int64_t kTransientVersion = 1;

void put_input_files(Writer& w, const std::vector<InputFile>& files) {
  w.put(static_cast<std::int64_t>(files.size()));
  for (const InputFile& f : files) {
    w.put(f.key);
    w.put(f.path);
    w.put(f.hash);
  }
}

// The fields after the header, in one order for writing and reading.
template <class Io, class Checkpoint>
void visit_transient(Io&& io, Checkpoint& c) {
  io(c.steps);
  io(c.time);
  io(c.time_step);
  io(c.history);
  io(c.probes);
  io(c.output_times);
  io(c.times);
  io(c.storage_rates);
  io(c.boundary_flows);
  io(c.probe_pressures);
  visit_flow(io, c.state);
  io(c.state.storage_rate);
}

}  // namespace

bool is_transient_checkpoint(std::string_view bytes) { return bytes.substr(0, kTransientMagic.size()) == kTransientMagic; }

std::string encode_transient_checkpoint(const TransientCheckpoint& c) {
  std::string bytes;
  Writer w([&](std::string_view piece) { bytes += piece; });
  for (char ch : kTransientMagic) w.put_raw(ch);
  w.put(kTransientVersion);
  w.put_raw(kByteOrderMark);
  w.put(c.scenario_hash);
  w.put(c.scenario_file);
  put_input_files(w, c.input_files);
  visit_transient([&](const auto& v) { w.put(v); }, c);
  w.put(static_cast<std::int64_t>(c.state.boundary_flows.size()));
  for (const hydro::BoundaryFlow& b : c.state.boundary_flows) {
    w.put(b.name);
    w.put(b.flow);
  }
  w.finish();
  return bytes;
}

TransientCheckpoint decode_transient_checkpoint(std::string_view file) {
  if (!is_transient_checkpoint(file)) throw CheckpointError("not a hydrodda transient checkpoint");
  Reader r = open_checked(file, kTransientMagic, kTransientVersion, "transient checkpoint");
  TransientCheckpoint c;
  r.get(c.scenario_hash);
  r.get(c.scenario_file);
  get_input_files(r, c.input_files);
  visit_transient([&](auto& v) { r.get(v); }, c);
  std::int64_t boundaries = 0;
  r.get(boundaries);
  if (boundaries < 0 || boundaries > kMaxCount) r.fail();
  for (std::int64_t i = 0; i < boundaries; ++i) {
    hydro::BoundaryFlow b;
    r.get(b.name);
    r.get(b.flow);
    c.state.boundary_flows.push_back(std::move(b));
  }
  r.expect_end();
  return c;
}

}  // namespace hydrodda::output

// The coupled transient run's checkpoint: its own magic line and version, the Writer and Reader
// and the engines' records above.
namespace hydrodda::output {

namespace {

constexpr std::string_view kCoupledTransientMagic = "hydrodda coupled transient checkpoint\n";
// 2: the DDA state's bonds broken so far (as the coupled checkpoint's format 16); 3: the bonds
// softening (as its format 17); 4: the coupling loop's float secant memory (as its format 18;
// always empty in time, the secant being for steady runs).
constexpr std::int64_t kCoupledTransientVersion = 5;

// The fields after the header and before the engines' states, in one order for both ways.
template <class Io, class Checkpoint>
void visit_coupled_transient(Io&& io, Checkpoint& c) {
  io(c.ended);
  io(c.steps);
  io(c.time);
  io(c.nominal_step);
  io(c.next_stop);
  io(c.history);
  io(c.probes);
  io(c.measure);
  io(c.output_times);
  io(c.times);
  io(c.storage_rates);
  io(c.boundary_flows);
  io(c.probe_pressures);
  io(c.fracture_counts);
}

}  // namespace

bool is_coupled_transient_checkpoint(std::string_view bytes) {
  return bytes.substr(0, kCoupledTransientMagic.size()) == kCoupledTransientMagic;
}

std::string encode_coupled_transient_checkpoint(const CoupledTransientCheckpoint& c) {
  return encode_coupled_transient_checkpoint(c, c.mechanics, c.coupling);
}

std::string encode_coupled_transient_checkpoint(const CoupledTransientCheckpoint& c, const dda::SystemState& mechanics,
                                                const coupling::LoopState& coupling) {
  std::string bytes;
  Writer w([&](std::string_view piece) { bytes += piece; });
  for (char ch : kCoupledTransientMagic) w.put_raw(ch);
  w.put(kCoupledTransientVersion);
  w.put_raw(kByteOrderMark);
  w.put(c.scenario_hash);
  w.put(c.scenario_file);
  put_input_files(w, c.input_files);
  visit_coupled_transient([&](const auto& v) { w.put(v); }, c);
  write_mechanics(w, mechanics);
  write_loop_state(w, coupling);
  w.put(coupling.flow.storage_rate);
  w.finish();
  return bytes;
}

CoupledTransientCheckpoint decode_coupled_transient_checkpoint(std::string_view file) {
  if (!is_coupled_transient_checkpoint(file)) throw CheckpointError("not a hydrodda coupled transient checkpoint");
  Reader r = open_checked(file, kCoupledTransientMagic, kCoupledTransientVersion, "coupled transient checkpoint");
  CoupledTransientCheckpoint c;
  r.get(c.scenario_hash);
  r.get(c.scenario_file);
  get_input_files(r, c.input_files);
  visit_coupled_transient([&](auto& v) { r.get(v); }, c);
  if (c.steps < 0 || c.next_stop < 0 || c.fracture_counts.size() % 5 != 0) r.fail();
  read_mechanics(r, c.mechanics);
  read_loop_state(r, c.coupling);
  r.get(c.coupling.flow.storage_rate);
  r.expect_end();
  return c;
}

}  // namespace hydrodda::output
