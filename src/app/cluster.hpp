#pragma once
// The MPI ranks a batch runs on, or just this process when pound was built without MPI or was
// not started by mpirun. MPI is started only under a launcher (mpirun sets OMPI_COMM_WORLD_SIZE,
// PMI_SIZE or PMIX_RANK), so a plain `pound` never pays for it or needs a launcher.
#include <memory>
#include <string>
#include <vector>

namespace pound::app {

class Cluster {
 public:
  Cluster();
  ~Cluster();
  Cluster(const Cluster&) = delete;
  Cluster& operator=(const Cluster&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_root() const { return rank_ == 0; }

  void barrier() const;
  // Every rank's strings, concatenated in rank order on rank 0; empty on the other ranks.
  std::vector<std::string> gather(const std::vector<std::string>& mine) const;
  // True on every rank if any rank passes true.
  bool any(bool mine) const;
  // The largest value any rank passes, on every rank.
  int max(int mine) const;

  // Whether this binary was built with MPI (Boost.MPI).
  static bool available();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace pound::app
