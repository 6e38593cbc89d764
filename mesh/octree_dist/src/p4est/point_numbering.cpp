#include "point_numbering.hpp"

#include <algorithm>
#include <bit>
#include <string>

#include "volmesh/core/errors.hpp"

namespace volmesh::octree_dist {
namespace {

// Sends each rank its part of `values` (grouped by destination, counts per rank); returns what
// this rank receives, grouped by source, and the counts per source.
template <class T>
std::vector<T> exchange(const std::vector<T>& values, const std::vector<int>& send_count, std::vector<int>& receive_count,
                        MPI_Datatype type, MPI_Comm comm) {
  const int ranks = static_cast<int>(send_count.size());
  receive_count.assign(ranks, 0);
  MPI_Alltoall(send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, comm);
  std::vector<int> send_offset(ranks + 1, 0), receive_offset(ranks + 1, 0);
  for (int r = 0; r < ranks; ++r) {
    send_offset[r + 1] = send_offset[r] + send_count[r];
    receive_offset[r + 1] = receive_offset[r] + receive_count[r];
  }
  std::vector<T> received(receive_offset[ranks]);
  MPI_Alltoallv(values.data(), send_count.data(), send_offset.data(), type, received.data(), receive_count.data(),
                receive_offset.data(), type, comm);
  return received;
}

constexpr std::int64_t kNotHeld = -1;

template <class Key>
PointNumbers number_keys(const std::vector<Key>& keys, const std::vector<int>& owner, MPI_Datatype key_type,
                         MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  std::vector<Key> owned;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (owner[i] == rank) owned.push_back(keys[i]);
  std::sort(owned.begin(), owned.end());
  const std::int64_t mine = static_cast<std::int64_t>(owned.size());
  std::int64_t first = 0;
  MPI_Exscan(&mine, &first, 1, MPI_INT64_T, MPI_SUM, comm);
  if (rank == 0) first = 0;  // MPI_Exscan leaves rank 0's result undefined
  PointNumbers out;
  MPI_Allreduce(&mine, &out.count, 1, MPI_INT64_T, MPI_SUM, comm);
  const auto own_number = [&](const Key& key) {
    const auto at = std::lower_bound(owned.begin(), owned.end(), key);
    return at == owned.end() || *at != key ? kNotHeld : first + (at - owned.begin());
  };

  // Requests grouped by owner.
  std::vector<std::size_t> asked;  // point per request, grouped by owner
  std::vector<int> ask_count(ranks, 0);
  out.id.assign(keys.size(), kNotHeld);
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (owner[i] == rank)
      out.id[i] = own_number(keys[i]);
    else
      ++ask_count[owner[i]];
  std::vector<int> ask_offset(ranks + 1, 0);
  for (int r = 0; r < ranks; ++r) ask_offset[r + 1] = ask_offset[r] + ask_count[r];
  asked.resize(ask_offset[ranks]);
  std::vector<Key> ask_keys(ask_offset[ranks]);
  std::vector<int> next(ask_offset.begin(), ask_offset.end() - 1);
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (owner[i] != rank) {
      asked[next[owner[i]]] = i;
      ask_keys[next[owner[i]]++] = keys[i];
    }
  std::vector<int> question_count;
  const std::vector<Key> questions = exchange(ask_keys, ask_count, question_count, key_type, comm);
  std::vector<std::int64_t> answers(questions.size());
  for (std::size_t q = 0; q < questions.size(); ++q) answers[q] = own_number(questions[q]);
  std::vector<int> answer_count;
  const std::vector<std::int64_t> numbers = exchange(answers, question_count, answer_count, MPI_INT64_T, comm);
  for (std::size_t a = 0; a < numbers.size(); ++a) out.id[asked[a]] = numbers[a];
  return out;
}

PointNumbers all_held(PointNumbers numbers, MPI_Comm comm) {
  if (std::count(numbers.id.begin(), numbers.id.end(), kNotHeld) == 0) return numbers;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  throw InputError("pieces: rank " + std::to_string(rank) +
                   " holds a point shared with another rank that its owner does not have there");
}

}  // namespace

PlaceKey place_key(const Vec3& x) {
  return {std::bit_cast<std::uint64_t>(x.x()), std::bit_cast<std::uint64_t>(x.y()), std::bit_cast<std::uint64_t>(x.z())};
}

PointNumbers number_points(const std::vector<GridKey>& keys, const std::vector<int>& owner, MPI_Comm comm) {
  return all_held(number_keys(keys, owner, MPI_UINT64_T, comm), comm);
}

PointNumbers number_points(const std::vector<PlaceKey>& keys, const std::vector<int>& owner, MPI_Comm comm) {
  MPI_Datatype three;
  MPI_Type_contiguous(3, MPI_UINT64_T, &three);
  MPI_Type_commit(&three);
  PointNumbers out = number_keys(keys, owner, three, comm);
  MPI_Type_free(&three);
  return all_held(std::move(out), comm);
}

}  // namespace volmesh::octree_dist
