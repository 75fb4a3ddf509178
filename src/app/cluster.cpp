#include "app/cluster.hpp"

#include <cstdlib>
#include <functional>
#include <stdexcept>

#ifdef POUND_HAVE_MPI
#include <boost/mpi/collectives.hpp>
#include <boost/mpi/communicator.hpp>
#include <boost/mpi/environment.hpp>
#include <boost/mpi/operations.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#endif

namespace pound::app {

namespace {

bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

}  // namespace

#ifdef POUND_HAVE_MPI

struct Cluster::Impl {
  boost::mpi::environment environment{boost::mpi::threading::single};
  boost::mpi::communicator world;
};

Cluster::Cluster() {
  if (!launched_by_mpirun()) return;
  impl_ = std::make_unique<Impl>();
  rank_ = impl_->world.rank();
  size_ = impl_->world.size();
}

Cluster::~Cluster() = default;

void Cluster::barrier() const {
  if (impl_) impl_->world.barrier();
}

std::vector<std::string> Cluster::gather(const std::vector<std::string>& mine) const {
  if (!impl_) return mine;
  std::vector<std::vector<std::string>> all;
  boost::mpi::gather(impl_->world, mine, all, 0);
  std::vector<std::string> joined;
  for (const auto& part : all) joined.insert(joined.end(), part.begin(), part.end());
  return joined;
}

bool Cluster::any(bool mine) const {
  if (!impl_) return mine;
  bool result = false;
  boost::mpi::all_reduce(impl_->world, mine, result, std::logical_or<bool>());
  return result;
}

int Cluster::max(int mine) const {
  if (!impl_) return mine;
  int result = 0;
  boost::mpi::all_reduce(impl_->world, mine, result, boost::mpi::maximum<int>());
  return result;
}

bool Cluster::available() { return true; }

#else

struct Cluster::Impl {};

Cluster::Cluster() {
  // Every rank would run every case into the same folders.
  if (launched_by_mpirun())
    throw std::runtime_error(
        "this pound was built without MPI (Boost.MPI not found): run it without mpirun, or "
        "rebuild with libboost-mpi-dev installed");
}
Cluster::~Cluster() = default;
void Cluster::barrier() const {}
std::vector<std::string> Cluster::gather(const std::vector<std::string>& mine) const {
  return mine;
}
bool Cluster::any(bool mine) const { return mine; }
int Cluster::max(int mine) const { return mine; }
bool Cluster::available() { return false; }

#endif

}  // namespace pound::app
