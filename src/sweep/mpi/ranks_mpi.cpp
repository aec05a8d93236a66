// SweepRanks over MPI, its calls made through the MPI plugin (mpi_plugin.hpp), loaded when an
// MPI launcher started the program.
//
// Rank 0 is the coordinator and a worker. Messages, all on MPI_COMM_WORLD:
//   0 → r  kPlan      the cases' commands, folders and columns (empty: the sweep never started)
//   r → 0  kRequest   "give me a case", with the result of the case r just ran, if any
//   0 → r  kAssign    a case index, or -1: nothing more to run
//   0 → r  kExitCode  the sweep's exit code, once sweep.csv is written
// Every wait is a nonblocking receive polled every 20 ms, so that a rank with nothing to do
// sleeps instead of spinning the core a case on the same host needs (Open MPI's blocking calls
// busy-wait).
// mpi.h for its version macros only: the calls are the plugin's.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#include <signal.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <thread>

#include "base/program_files.hpp"
#include "sweep/mpi/mpi_plugin.hpp"
#include "sweep/ranks.hpp"

namespace hydrodda::sweep {

namespace {

namespace fs = std::filesystem;

enum Tag : int { kPlan = 1, kRequest = 2, kAssign = 3, kExitCode = 4 };
constexpr auto kPollInterval = std::chrono::milliseconds(20);
constexpr int kAnyRank = -1;

// The plugin beside the executable, else where the build made it; loaded once, never unloaded.
const HydroddaMpiCalls& load_mpi() {
  // global: Open MPI dlopens its own components, which look for its symbols.
  const base::Plugin library("hydrodda_mpi.so", HYDRODDA_MPI_PLUGIN, "the MPI plugin", true);
  return *library.entry<decltype(&hydrodda_mpi_calls)>("hydrodda_mpi_calls")();
}

const HydroddaMpiCalls& mpi() {
  static const HydroddaMpiCalls& loaded = load_mpi();
  return loaded;
}

// Strings packed as (8-byte length, bytes) each, so that any text crosses intact.
std::string pack(const std::vector<std::string>& fields) {
  std::string out;
  for (const std::string& f : fields) {
    const std::uint64_t n = f.size();
    out.append(reinterpret_cast<const char*>(&n), sizeof n);
    out += f;
  }
  return out;
}

std::vector<std::string> unpack(const std::string& bytes) {
  std::vector<std::string> fields;
  std::size_t at = 0;
  while (at + sizeof(std::uint64_t) <= bytes.size()) {
    std::uint64_t n = 0;
    std::memcpy(&n, bytes.data() + at, sizeof n);
    at += sizeof n;
    if (n > bytes.size() - at) throw std::runtime_error("sweep over MPI: a message arrived cut short");
    fields.push_back(bytes.substr(at, n));
    at += n;
  }
  return fields;
}

// The plan: columns first (their count, then each), then per case its folder, its log and its
// arguments (their count, then each).
std::string pack_plan(const SweepPlan& plan) {
  std::vector<std::string> f{std::to_string(plan.columns.size())};
  f.insert(f.end(), plan.columns.begin(), plan.columns.end());
  for (std::size_t i = 0; i < plan.commands.size(); ++i) {
    f.push_back(plan.folders[i].string());
    f.push_back(plan.commands[i].log.string());
    f.push_back(std::to_string(plan.commands[i].arguments.size()));
    f.insert(f.end(), plan.commands[i].arguments.begin(), plan.commands[i].arguments.end());
  }
  return pack(f);
}

SweepPlan unpack_plan(const std::string& bytes) {
  const std::vector<std::string> f = unpack(bytes);
  SweepPlan plan;
  std::size_t at = 0;
  const auto next = [&]() -> const std::string& {
    if (at >= f.size()) throw std::runtime_error("sweep over MPI: the plan arrived cut short");
    return f[at++];
  };
  for (std::size_t n = std::stoul(next()); n > 0; --n) plan.columns.push_back(next());
  while (at < f.size()) {
    plan.folders.push_back(next());
    ChildCommand command;
    command.log = next();
    for (std::size_t n = std::stoul(next()); n > 0; --n) command.arguments.push_back(next());
    plan.commands.push_back(std::move(command));
  }
  return plan;
}

// A request: the case just run (-1 for none), whether this rank was interrupted, its result.
std::string pack_request(long long index, bool interrupted, const CaseResult& r) {
  std::vector<std::string> f{std::to_string(index), interrupted ? "1" : "0", std::string(status_name(r.status)), r.converged, r.iterations,
                             r.message};
  for (const auto& c : r.columns) f.push_back(c ? "=" + *c : "");
  return pack(f);
}

struct Request {
  long long index = -1;
  bool interrupted = false;
  CaseResult result;
};

Request unpack_request(const std::string& bytes) {
  const std::vector<std::string> f = unpack(bytes);
  if (f.size() < 6) throw std::runtime_error("sweep over MPI: a case's result arrived cut short");
  Request q{std::stoll(f[0]), f[1] == "1", {}};
  q.result.status = status_from_name(f[2]);
  q.result.converged = f[3];
  q.result.iterations = f[4];
  q.result.message = f[5];
  for (std::size_t k = 6; k < f.size(); ++k)
    q.result.columns.push_back(f[k].empty() ? std::nullopt : std::optional<std::string>(f[k].substr(1)));
  return q;
}

void send_bytes(const std::string& bytes, int to, Tag tag) {
  mpi().send(bytes.data(), static_cast<int>(bytes.size()), to, tag);
}

// Waits, sleeping between polls, for one message of `tag` from `from` (any when kAnyRank)
// and returns its bytes.
std::string receive_bytes(int from, Tag tag, int* source = nullptr) {
  int sender = 0;
  int count = 0;
  while (!mpi().probe(from, tag, &sender, &count)) std::this_thread::sleep_for(kPollInterval);
  std::string bytes(static_cast<std::size_t>(count), '\0');
  mpi().receive(bytes.data(), count, sender, tag);
  if (source) *source = sender;
  return bytes;
}

long long receive_number(int from, Tag tag) { return std::stoll(receive_bytes(from, tag)); }

// One case run as a child process on this rank, an interrupt passed on to it.
class LocalCase {
 public:
  LocalCase(const SweepPlan& plan, std::size_t index, const std::function<bool()>& stop_requested)
      : plan_(plan), index_(index), stop_requested_(stop_requested) {
    try {
      pid_ = start_child_process(plan.commands[index]);
    } catch (const std::runtime_error& e) {
      result_ = CaseResult{};
      result_->status = CaseStatus::failed;
      result_->message = e.what();
      result_->columns.assign(plan.columns.size(), std::nullopt);
    }
  }
  std::size_t index() const { return index_; }
  // The result once the case has ended, else nothing.
  const std::optional<CaseResult>& poll() {
    if (result_) return result_;
    if (stop_requested_() && !forwarded_) {
      ::kill(pid_, SIGINT);
      forwarded_ = true;
    }
    if (const std::optional<int> code = poll_child_process(pid_))
      result_ = read_case_result(plan_.folders[index_].filename().string(), plan_.folders[index_], *code,
                                      plan_.columns, stop_requested_());
    return result_;
  }

 private:
  const SweepPlan& plan_;
  std::size_t index_;
  const std::function<bool()>& stop_requested_;
  int pid_ = -1;
  bool forwarded_ = false;
  std::optional<CaseResult> result_;
};

}  // namespace

SweepRanks::SweepRanks(std::function<bool()> stop_requested) : stop_requested_(std::move(stop_requested)) {
  const bool launched = launcher_rank_count() > 0 || std::getenv("PMIX_RANK");
  if (!launched) return;
  mpi().join(&rank_, &size_);
  joined_ = true;
}

SweepRanks::~SweepRanks() {
  if (joined_) mpi().leave();
}

std::vector<std::size_t> SweepRanks::run_cases(const SweepPlan& plan, const CaseFinished& finished) {
  const std::string plan_bytes = pack_plan(plan);
  for (int r = 1; r < size_; ++r) send_bytes(plan_bytes, r, kPlan);
  plan_sent_ = true;

  const std::size_t n = plan.commands.size();
  std::size_t next = 0;
  int released = 0;  // ranks told that nothing more will run
  bool stopping = false;
  std::optional<LocalCase> local;
  for (;;) {
    stopping = stopping || stop_requested_();
    if (!local && !stopping && next < n) local.emplace(plan, next++, stop_requested_);
    bool progressed = false;
    int waiting_source = 0;
    int waiting_count = 0;
    if (mpi().probe(kAnyRank, kRequest, &waiting_source, &waiting_count)) {
      int source = 0;
      const Request q = unpack_request(receive_bytes(waiting_source, kRequest, &source));
      if (q.index >= 0) finished(static_cast<std::size_t>(q.index), q.result, source);
      stopping = stopping || q.interrupted;
      const long long assigned = !stopping && next < n ? static_cast<long long>(next++) : -1;
      send_bytes(std::to_string(assigned), source, kAssign);
      if (assigned < 0) ++released;
      progressed = true;
    }
    if (local && local->poll()) {
      finished(local->index(), *local->poll(), 0);
      local.reset();
      progressed = true;
    }
    if (!local && released == size_ - 1 && (next >= n || stopping)) break;
    if (!progressed) std::this_thread::sleep_for(kPollInterval);
  }
  cases_done_ = true;
  std::vector<std::size_t> never_started;
  for (std::size_t i = next; i < n; ++i) never_started.push_back(i);
  return never_started;
}

void SweepRanks::finish(int exit_code) {
  if (size_ < 2) return;
  // The sweep failed while cases were out (sweep.csv could not be written): the other ranks
  // wait for cases that will never be handed out, so the job ends here.
  if (plan_sent_ && !cases_done_) mpi().abort(exit_code);
  if (!plan_sent_)
    for (int r = 1; r < size_; ++r) send_bytes("", r, kPlan);
  plan_sent_ = true;
  for (int r = 1; r < size_; ++r) send_bytes(std::to_string(exit_code), r, kExitCode);
}

int SweepRanks::serve() {
  const std::string plan_bytes = receive_bytes(0, kPlan);
  if (!plan_bytes.empty()) {
    const SweepPlan plan = unpack_plan(plan_bytes);
    long long done = -1;
    CaseResult result;
    for (;;) {
      send_bytes(pack_request(done, stop_requested_(), result), 0, kRequest);
      const long long assigned = receive_number(0, kAssign);
      if (assigned < 0) break;
      LocalCase running(plan, static_cast<std::size_t>(assigned), stop_requested_);
      while (!running.poll()) std::this_thread::sleep_for(kPollInterval);
      done = assigned;
      result = *running.poll();
    }
  }
  return static_cast<int>(receive_number(0, kExitCode));
}

// The library as MPI_Get_library_version names it, up to its first comma, from the header the
// plugin was built with (calling it would load the plugin for --version).
std::string SweepRanks::build_description() {
#if defined(OMPI_MAJOR_VERSION)
  return "with MPI (Open MPI v" + std::to_string(OMPI_MAJOR_VERSION) + "." + std::to_string(OMPI_MINOR_VERSION) + "." +
         std::to_string(OMPI_RELEASE_VERSION) + ")";
#elif defined(MPICH_VERSION)
  return "with MPI (MPICH " MPICH_VERSION ")";
#else
  return "with MPI (MPI " + std::to_string(MPI_VERSION) + "." + std::to_string(MPI_SUBVERSION) + ")";
#endif
}

}  // namespace hydrodda::sweep
