#pragma once
// The tests' view of all ranks at once: every rank's values on every rank.
#include <mpi.h>

#include <vector>

namespace volmesh::test {

// Every rank's values, concatenated in rank order, on every rank; rank_of (optional): each
// value's rank.
template <class T>
std::vector<T> gather_to_all(const std::vector<T>& mine, MPI_Datatype type, std::vector<int>* rank_of = nullptr) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(ranks), offsets(ranks + 1, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 0; r < ranks; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<T> all(offsets[ranks]);
  MPI_Allgatherv(mine.data(), count, type, all.data(), counts.data(), offsets.data(), type, MPI_COMM_WORLD);
  if (rank_of) {
    rank_of->clear();
    for (int r = 0; r < ranks; ++r) rank_of->insert(rank_of->end(), counts[r], r);
  }
  return all;
}

}  // namespace volmesh::test
