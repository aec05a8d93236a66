#pragma once
// The MPI calls a sweep over ranks makes (ranks_mpi.cpp), behind the one entry point of the MPI
// plugin (mpi_plugin.cpp, built as hydrodda_mpi.so), which ranks_mpi.cpp loads with dlopen
// when an MPI launcher started the program: Open MPI's libraries (libmpi, ORTE, OPAL, hwloc,
// libevent) are loaded only by the ranks of such a job, not by every run, check or --version.
// Messages are bytes on MPI_COMM_WORLD; a rank of −1 is any rank.

extern "C" {
struct HydroddaMpiCalls {
  // MPI_Init, then this rank and the job's size.
  void (*join)(int* rank, int* size);
  // MPI_Finalize.
  void (*leave)();
  void (*send)(const char* bytes, int count, int to, int tag);
  // Whether a message of `tag` from `from` waits (MPI_Iprobe); if so, its source and length.
  int (*probe)(int from, int tag, int* source, int* count);
  void (*receive)(char* bytes, int count, int from, int tag);
  // MPI_Abort on MPI_COMM_WORLD.
  void (*abort)(int code);
};
__attribute__((visibility("default"))) const HydroddaMpiCalls* hydrodda_mpi_calls();
}
