#include "numerics/nested_dissection.hpp"

#include <metis.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "numerics/parallel.hpp"
#include "base/metis_lock.hpp"
#include "base/program_files.hpp"

extern char** environ;

namespace hydrodda::numerics {
namespace {

namespace fs = std::filesystem;

// A graph in METIS's compressed form: the neighbours of v are adjncy[xadj[v] … xadj[v + 1]).
struct Graph {
  std::vector<idx_t> xadj;
  std::vector<idx_t> adjncy;
  idx_t size() const { return xadj.empty() ? 0 : static_cast<idx_t>(xadj.size()) - 1; }
};

void check(int status, const char* what) {
  if (status != METIS_OK) throw std::runtime_error(std::string("METIS could not ") + what + " (status " +
                                                   std::to_string(status) + ")");
}

// The graph of a symmetric matrix from its upper triangle, without the diagonal.
Graph graph_of(const SparseMatrix& upper) {
  const int n = static_cast<int>(upper.cols());
  std::vector<idx_t> degree(n, 0);
  for (int j = 0; j < n; ++j)
    for (SparseMatrix::InnerIterator it(upper, j); it; ++it)
      if (it.row() != j) {
        ++degree[it.row()];
        ++degree[j];
      }
  Graph g;
  g.xadj.assign(n + 1, 0);
  for (int v = 0; v < n; ++v) g.xadj[v + 1] = g.xadj[v] + degree[v];
  g.adjncy.resize(g.xadj[n]);
  std::vector<idx_t> next(g.xadj.begin(), g.xadj.end() - 1);
  for (int j = 0; j < n; ++j)
    for (SparseMatrix::InnerIterator it(upper, j); it; ++it)
      if (it.row() != j) {
        g.adjncy[next[it.row()]++] = j;
        g.adjncy[next[j]++] = static_cast<idx_t>(it.row());
      }
  return g;
}

// METIS_NodeND of `g`: the vertices in pivot order.
std::vector<idx_t> order_whole(Graph& g) {
  idx_t n = g.size();
  std::vector<idx_t> order(n), inverse(n);
  if (n == 0) return order;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  const std::lock_guard<std::mutex> one_at_a_time(base::metis_lock());
  check(METIS_NodeND(&n, g.xadj.data(), g.adjncy.data(), nullptr, options, order.data(), inverse.data()),
        "order the flow matrix");
  return order;
}

// The subgraph on `vertices` (ascending), numbered in their order.
Graph subgraph(const Graph& g, const std::vector<idx_t>& vertices) {
  std::vector<idx_t> local(g.size(), -1);
  for (std::size_t k = 0; k < vertices.size(); ++k) local[vertices[k]] = static_cast<idx_t>(k);
  Graph s;
  s.xadj.reserve(vertices.size() + 1);
  s.xadj.push_back(0);
  for (idx_t v : vertices) {
    for (idx_t e = g.xadj[v]; e < g.xadj[v + 1]; ++e)
      if (local[g.adjncy[e]] >= 0) s.adjncy.push_back(local[g.adjncy[e]]);
    s.xadj.push_back(static_cast<idx_t>(s.adjncy.size()));
  }
  return s;
}

// The helper beside the program, else where the build made it.
fs::path helper_path() { return base::find_beside_program("hydrodda_order", HYDRODDA_ORDER_PROGRAM); }

// The helper process ordering one graph (ordering/order_graph.cpp), through a socket
// (MSG_NOSIGNAL: a helper that died is a failed order, not a SIGPIPE here). Killed and waited
// for if its order is not taken.
class OrderingProcess {
 public:
  // Started and sent the graph; false where the helper could not be started.
  bool start(const Graph& g) {
    int ends[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return false;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, ends[1], 0);  // dup2 clears close-on-exec
    posix_spawn_file_actions_adddup2(&actions, ends[1], 1);
    const std::string path = helper_path().string();
    char* argv[] = {const_cast<char*>(path.c_str()), nullptr};
    pid_t pid = -1;
    const int spawned = ::posix_spawn(&pid, path.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(ends[1]);
    if (spawned != 0) {
      ::close(ends[0]);
      return false;
    }
    pid_ = pid;
    socket_ = ends[0];
    const std::int64_t header[2] = {g.size(), static_cast<std::int64_t>(g.adjncy.size())};
    if (!send_all(header, sizeof header) || !send_all(g.xadj.data(), g.xadj.size() * sizeof(idx_t)) ||
        !send_all(g.adjncy.data(), g.adjncy.size() * sizeof(idx_t))) {
      stop();
      return false;
    }
    return true;
  }
  ~OrderingProcess() { stop(); }

  // Its order of the graph's `count` vertices; none when it failed.
  std::optional<std::vector<idx_t>> take(std::size_t count) {
    std::vector<idx_t> order(count);
    char* bytes = reinterpret_cast<char*>(order.data());
    std::size_t left = count * sizeof(idx_t);
    while (left > 0) {
      const ssize_t n = ::recv(socket_, bytes, left, 0);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      bytes += n;
      left -= static_cast<std::size_t>(n);
    }
    const int status = wait();
    if (left > 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
    return order;
  }

 private:
  bool send_all(const void* data, std::size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
      const ssize_t n = ::send(socket_, bytes, size, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      bytes += n;
      size -= static_cast<std::size_t>(n);
    }
    return true;
  }
  int wait() {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    ::close(socket_);
    pid_ = socket_ = -1;
    return status;
  }
  void stop() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    wait();
  }

  pid_t pid_ = -1;
  int socket_ = -1;
};

}  // namespace

// Pseudocode: part = METIS_ComputeVertexSeparator(G)       0, 1: the halves; 2: the separator
//             side by side: order_h = METIS_NodeND(G[half h]), h = 0 here, 1 in the helper
//             order = order_0, order_1, separator           (each in its own numbering → G's)
// No edge joins the halves, so eliminating either never fills the other: the factor of the
// halves is two independent factors, the separator's block last, as METIS's own first cut.
// METIS cannot order two graphs at once in one process (its random number generator is
// shared: two orderings made on two threads come out different from run to run), hence the
// helper; a fork of this process would cost the copies of every page it then writes.
FillOrder order_by_nested_dissection(const SparseMatrix& upper, bool with_helper) {
  Graph g = graph_of(upper);
  const idx_t n = g.size();
  const auto as_order = [](const std::vector<idx_t>& order) { return FillOrder{std::vector<int>(order.begin(), order.end())}; };
  if (n < kSplitFrom) return as_order(order_whole(g));

  idx_t count = n, separator_size = 0;
  std::vector<idx_t> part(n);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  {
    const std::lock_guard<std::mutex> one_at_a_time(base::metis_lock());
    check(METIS_ComputeVertexSeparator(&count, g.xadj.data(), g.adjncy.data(), nullptr, options, &separator_size,
                                       part.data()),
          "split the flow matrix's graph");
  }
  std::vector<idx_t> half[2], separator;
  for (idx_t v = 0; v < n; ++v) (part[v] == 2 ? separator : half[part[v]]).push_back(v);
  if (half[0].empty() || half[1].empty()) return as_order(order_whole(g));

  Graph second = subgraph(g, half[1]);
  OrderingProcess helper;
  const bool aside = with_helper && numerics::two_threads_available() && helper.start(second);
  std::vector<idx_t> order[2];
  Graph first = subgraph(g, half[0]);
  order[0] = order_whole(first);
  // Where the helper could not start or failed, this process orders the half: the same order.
  std::optional<std::vector<idx_t>> taken = aside ? helper.take(half[1].size()) : std::nullopt;
  order[1] = taken ? std::move(*taken) : order_whole(second);
  for (int h = 0; h < 2; ++h)
    for (idx_t& v : order[h]) v = half[h][v];

  FillOrder out;
  out.order.reserve(n);
  for (const std::vector<idx_t>* list : {&order[0], &order[1], &separator})
    out.order.insert(out.order.end(), list->begin(), list->end());
  out.halves[0] = static_cast<int>(half[0].size());
  out.halves[1] = static_cast<int>(half[1].size());
  return out;
}

std::vector<int> FillOrder::parts() const {
  if (halves[0] == 0 && halves[1] == 0) return {};
  std::vector<int> part(order.size(), 2);
  for (int k = 0; k < halves[0] + halves[1]; ++k) part[order[k]] = k < halves[0] ? 0 : 1;
  return part;
}

}  // namespace hydrodda::numerics
