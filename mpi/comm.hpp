// The thin layer dtlab-mpi needs over MPI's C API, and nothing more: the session, one exchange
// step (every rank sends each other rank a list), the global "any" reduction, sums and maxima,
// and gathering lists at one rank. Lists are of trivially copyable types, sent as bytes.
// Everything else (tiles, rounds, what is sent) is MPI-free library code (algorithms/distributed).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace dtlab::mpi {

// MPI_Init / MPI_Finalize around the program (MPI_THREAD_FUNNELED: only the main thread calls MPI).
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

class Comm {
 public:
  Comm() : comm_(MPI_COMM_WORLD) {}
  int rank() const;
  int size() const;

  // Sends out[r] to rank r (every rank calls it with size() lists); returns the list each rank
  // sent here, by rank. InputError when a message would exceed MPI's int byte counts.
  template <class T>
  std::vector<std::vector<T>> exchange(const std::vector<std::vector<T>>& out) const {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<std::vector<std::uint8_t>> bytes(out.size());
    for (std::size_t r = 0; r < out.size(); ++r) {
      bytes[r].resize(out[r].size() * sizeof(T));
      if (!out[r].empty()) std::memcpy(bytes[r].data(), out[r].data(), bytes[r].size());
    }
    const std::vector<std::vector<std::uint8_t>> in = exchange_bytes(bytes);
    std::vector<std::vector<T>> result(in.size());
    for (std::size_t r = 0; r < in.size(); ++r) {
      result[r].resize(in[r].size() / sizeof(T));
      if (!in[r].empty()) std::memcpy(result[r].data(), in[r].data(), in[r].size());
    }
    return result;
  }
  // The lists of every rank, concatenated in rank order, at `root` (empty elsewhere).
  template <class T>
  std::vector<T> gather(const std::vector<T>& mine, int root) const {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<std::uint8_t> bytes(mine.size() * sizeof(T));
    if (!mine.empty()) std::memcpy(bytes.data(), mine.data(), bytes.size());
    const std::vector<std::uint8_t> all = gather_bytes(bytes, root);
    std::vector<T> result(all.size() / sizeof(T));
    if (!all.empty()) std::memcpy(result.data(), all.data(), all.size());
    return result;
  }
  bool any(bool mine) const;
  std::uint64_t sum(std::uint64_t mine) const;
  double max(double mine) const;
  void barrier() const;

 private:
  std::vector<std::vector<std::uint8_t>> exchange_bytes(const std::vector<std::vector<std::uint8_t>>& out) const;
  std::vector<std::uint8_t> gather_bytes(const std::vector<std::uint8_t>& mine, int root) const;
  MPI_Comm comm_;
};

}  // namespace dtlab::mpi
