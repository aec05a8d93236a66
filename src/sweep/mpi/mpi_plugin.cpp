// The MPI plugin: the project's one file that calls MPI (mpi_plugin.hpp), over MPI's C
// interface only (the C++ bindings, removed from the standard, would need their own library).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include "sweep/mpi/mpi_plugin.hpp"

namespace {

void join(int* rank, int* size) {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
}

void leave() { MPI_Finalize(); }

void send(const char* bytes, int count, int to, int tag) {
  MPI_Send(bytes, count, MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

int probe(int from, int tag, int* source, int* count) {
  MPI_Status status;
  int arrived = 0;
  MPI_Iprobe(from < 0 ? MPI_ANY_SOURCE : from, tag, MPI_COMM_WORLD, &arrived, &status);
  if (!arrived) return 0;
  *source = status.MPI_SOURCE;
  MPI_Get_count(&status, MPI_CHAR, count);
  return 1;
}

void receive(char* bytes, int count, int from, int tag) {
  MPI_Recv(bytes, count, MPI_CHAR, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}

void abort_job(int code) { MPI_Abort(MPI_COMM_WORLD, code); }

constexpr HydroddaMpiCalls kCalls{join, leave, send, probe, receive, abort_job};

}  // namespace

const HydroddaMpiCalls* hydrodda_mpi_calls() { return &kCalls; }
