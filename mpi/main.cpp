// The `dtlab-mpi` executable: dtlab's subcommands that run on several processes (book §13.3),
// under mpirun. Built only where MPI is found, so that `dtlab` itself needs no MPI.
//
// Errors: bad options and input are found by every rank alike before any message moves: rank 0
// names them and every rank exits 1. An error after that (one rank out of memory, an MPI
// failure) ends the whole job with MPI_Abort, exit 1, so that no rank waits for ever on a rank
// that is gone.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <new>

#include "kernel/error.hpp"
#include "mpi/comm.hpp"
#include "mpi/delaunay_command.hpp"

int main(int argc, char** argv) {
  dtlab::mpi::Session session(argc, argv);
  const dtlab::mpi::Comm comm;
  const bool root = comm.rank() == 0;
  CLI::App app{"dtlab-mpi: dtlab's Delaunay triangulation over MPI processes (run it under mpirun)"};
  app.require_subcommand(1, 1);
  dtlab::mpi::DelaunayArgs delaunay;
  dtlab::mpi::add_delaunay(app, delaunay);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return root ? app.exit(e) : 0;
    if (root) std::cerr << "dtlab-mpi: " << e.what() << " (see --help)\n";
    return 1;
  }
  dtlab::mpi::Prepared prepared;
  try {
    prepared = dtlab::mpi::prepare(delaunay);  // every rank alike, no message yet
  } catch (const dtlab::Error& e) {
    if (root) std::cerr << "dtlab-mpi: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    // Maybe on this rank only: the others may already wait on a message, so the job ends here.
    std::cerr << "dtlab-mpi: rank " << comm.rank()
              << ": out of memory reading or generating the points (every rank holds them all)\n";
    MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
  try {
    return dtlab::mpi::run_delaunay(comm, delaunay, prepared);
  } catch (const std::bad_alloc&) {
    std::cerr << "dtlab-mpi: rank " << comm.rank() << ": out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << "dtlab-mpi: rank " << comm.rank() << ": " << e.what() << "\n";
  }
  MPI_Abort(MPI_COMM_WORLD, 1);
  return 1;
}
