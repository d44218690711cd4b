#include "mpi/comm.hpp"

#include <limits>
#include <numeric>

#include "kernel/error.hpp"

namespace dtlab::mpi {
namespace {

void check(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw InternalError(std::string("MPI: ") + what + ": " + std::string(text, static_cast<std::size_t>(length)));
}

int as_count(std::size_t bytes, const char* what) {
  if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw InputError(std::string("MPI: ") + what + ": " + std::to_string(bytes) +
                     " bytes exceed one message's limit (2^31 - 1); use more ranks");
  return static_cast<int>(bytes);
}

}  // namespace

Session::Session(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
}

Session::~Session() { MPI_Finalize(); }

int Comm::rank() const {
  int r = 0;
  check(MPI_Comm_rank(comm_, &r), "MPI_Comm_rank");
  return r;
}

int Comm::size() const {
  int s = 0;
  check(MPI_Comm_size(comm_, &s), "MPI_Comm_size");
  return s;
}

std::vector<std::vector<std::uint8_t>> Comm::exchange_bytes(const std::vector<std::vector<std::uint8_t>>& out) const {
  const int n = size();
  if (static_cast<int>(out.size()) != n)
    throw InternalError("MPI exchange: " + std::to_string(out.size()) + " lists for " + std::to_string(n) + " ranks");
  std::vector<int> send_counts(n), send_offsets(n), receive_counts(n), receive_offsets(n);
  std::size_t total = 0;
  for (int r = 0; r < n; ++r) {
    send_counts[r] = as_count(out[r].size(), "exchange");
    send_offsets[r] = as_count(total, "exchange");
    total += out[r].size();
  }
  std::vector<std::uint8_t> send(total);
  for (int r = 0; r < n; ++r) std::copy(out[r].begin(), out[r].end(), send.begin() + send_offsets[r]);
  check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm_), "MPI_Alltoall");
  std::size_t received = 0;
  for (int r = 0; r < n; ++r) {
    receive_offsets[r] = as_count(received, "exchange");
    received += static_cast<std::size_t>(receive_counts[r]);
  }
  std::vector<std::uint8_t> receive(received);
  check(MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, receive.data(),
                      receive_counts.data(), receive_offsets.data(), MPI_BYTE, comm_),
        "MPI_Alltoallv");
  std::vector<std::vector<std::uint8_t>> in(n);
  for (int r = 0; r < n; ++r)
    in[r].assign(receive.begin() + receive_offsets[r], receive.begin() + receive_offsets[r] + receive_counts[r]);
  return in;
}

std::vector<std::uint8_t> Comm::gather_bytes(const std::vector<std::uint8_t>& mine, int root) const {
  const int n = size();
  const int count = as_count(mine.size(), "gather");
  std::vector<int> counts(n), offsets(n);
  check(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm_), "MPI_Gather");
  std::vector<std::uint8_t> all;
  if (rank() == root) {
    std::size_t total = 0;
    for (int r = 0; r < n; ++r) {
      offsets[r] = as_count(total, "gather");
      total += static_cast<std::size_t>(counts[r]);
    }
    all.resize(total);
  }
  check(MPI_Gatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, root, comm_),
        "MPI_Gatherv");
  return all;
}

bool Comm::any(bool mine) const {
  int in = mine ? 1 : 0, out = 0;
  check(MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LOR, comm_), "MPI_Allreduce");
  return out != 0;
}

std::uint64_t Comm::sum(std::uint64_t mine) const {
  std::uint64_t out = 0;
  check(MPI_Allreduce(&mine, &out, 1, MPI_UINT64_T, MPI_SUM, comm_), "MPI_Allreduce");
  return out;
}

double Comm::max(double mine) const {
  double out = 0;
  check(MPI_Allreduce(&mine, &out, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce");
  return out;
}

void Comm::barrier() const { check(MPI_Barrier(comm_), "MPI_Barrier"); }

}  // namespace dtlab::mpi
