#include "volmesh/runs/distributed.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <iostream>
#include <type_traits>

#include "volmesh/core/errors.hpp"
#include "volmesh/fem/parallel.hpp"
#include "volmesh/io/partitioned_io.hpp"
#include "volmesh/partition/part_mesh.hpp"
#include "volmesh/partition/partition.hpp"

namespace volmesh::cli {
namespace {

// A flat byte image of plain vectors and strings, read back in the same order.
class Bytes {
 public:
  explicit Bytes(std::vector<char>& data) : data_(data) {}
  template <class T>
  void put(const std::vector<T>& v) {
    // Plain numbers, or fixed-size Eigen vectors of them (Vec3: three doubles).
    static_assert(std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec3>);
    put_size(v.size());
    const char* p = reinterpret_cast<const char*>(v.data());
    data_.insert(data_.end(), p, p + v.size() * sizeof(T));
  }
  void put(const std::vector<std::string>& v) {
    put_size(v.size());
    for (const std::string& s : v) put(std::vector<char>(s.begin(), s.end()));
  }
  template <class T>
  void get(std::vector<T>& v) {
    v.resize(get_size());
    std::memcpy(static_cast<void*>(v.data()), data_.data() + at_, v.size() * sizeof(T));
    at_ += v.size() * sizeof(T);
  }
  void get(std::vector<std::string>& v) {
    v.resize(get_size());
    for (std::string& s : v) {
      std::vector<char> c;
      get(c);
      s.assign(c.begin(), c.end());
    }
  }

 private:
  void put_size(std::size_t n) {
    const char* p = reinterpret_cast<const char*>(&n);
    data_.insert(data_.end(), p, p + sizeof n);
  }
  std::size_t get_size() {
    std::size_t n = 0;
    std::memcpy(&n, data_.data() + at_, sizeof n);
    at_ += sizeof n;
    return n;
  }
  std::vector<char>& data_;
  std::size_t at_ = 0;
};

// The PolyMesh arrays, each as one vector (Vec3 is three doubles, without padding).
template <class Io>
void mesh_arrays(Io& io, PolyMesh& mesh) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  io(mesh.points);
  io(mesh.face_offsets);
  io(mesh.face_vertices);
  io(mesh.owner);
  io(mesh.neighbour);
  io(mesh.face_tag);
  io(mesh.cell_region);
  io(mesh.tag_names);
}

// A piece's arrays, each as one vector.
template <class Io>
void cell_list_arrays(Io& io, CellList& list) {
  io(list.points);
  io(list.point_ids);
  io(list.cell_ids);
  io(list.cell_region);
  io(list.cell_kind);
  io(list.cell_begin);
  io(list.items);
  io(list.tag_names);
  io(list.tagged_tag);
  io(list.tagged_begin);
  io(list.tagged_vertices);
}

}  // namespace

PolyMesh mesh_on_rank_zero(const std::function<PolyMesh()>& make, std::vector<double>* numbers) {
  const bool shared = fem::ranks() > 1;
  PolyMesh mesh;
  std::vector<char> bytes;
  fem::stage("mesh", [&] {
    if (fem::rank() != 0) return;
    mesh = make();
    if (!shared) return;
    Bytes out(bytes);
    auto put = [&out](auto& v) { out.put(v); };
    mesh_arrays(put, mesh);
    if (numbers) out.put(*numbers);
  });
  if (!shared) return mesh;
  fem::broadcast(bytes);
  if (fem::rank() != 0) {
    Bytes in(bytes);
    auto get = [&in](auto& v) { in.get(v); };
    mesh_arrays(get, mesh);
    if (numbers) in.get(*numbers);
  }
  return mesh;
}

PolyMesh read_pieces_on_ranks(const std::filesystem::path& pvtu, std::vector<Index>& cell_rank) {
  std::vector<std::filesystem::path> files;
  fem::stage("mesh", [&] {
    files = pvtu_piece_files(pvtu);
    if (files.size() != std::size_t(fem::ranks()))
      throw InputError(pvtu.string() + ": " + std::to_string(files.size()) + " pieces for " +
                       std::to_string(fem::ranks()) + " ranks (run it with mpirun -np " +
                       std::to_string(files.size()) + ", or repartition with volmesh partition --parts " +
                       std::to_string(fem::ranks()) + ")");
  });
  std::vector<char> bytes;
  fem::stage("mesh", [&] {
    CellList mine = read_vtu_piece(files[fem::rank()]);
    Bytes out(bytes);
    auto put = [&out](auto& v) { out.put(v); };
    cell_list_arrays(put, mine);
  });
  std::vector<std::vector<char>> all = fem::gather_bytes_to_all(bytes);
  std::vector<CellList> pieces(all.size());
  for (std::size_t r = 0; r < all.size(); ++r) {
    Bytes in(all[r]);
    auto get = [&in](auto& v) { in.get(v); };
    cell_list_arrays(get, pieces[r]);
  }
  PolyMesh mesh;
  fem::stage("mesh", [&] { mesh = stitch_pieces(pieces, pvtu.string(), &cell_rank); });
  return mesh;
}

void require_cell_per_rank(std::int64_t cells) {
  const int ranks = fem::ranks();
  if (ranks > cells)
    throw InputError(std::to_string(ranks) + " ranks for a mesh of " + std::to_string(cells) +
                     " cells: give every rank at least one cell (fewer ranks, or a finer mesh)");
}

std::vector<Index> partition_for_ranks(const PolyMesh& mesh) {
  const int ranks = fem::ranks();
  require_cell_per_rank(mesh.num_cells());
  std::vector<Index> cell_rank;
  std::vector<char> bytes;
  fem::stage("partition", [&] {
    if (fem::rank() != 0) return;
    PartitionOptions options;
    options.parts = ranks;
    cell_rank = partition_mesh(mesh, options).cell_part;
    Bytes(bytes).put(cell_rank);
  });
  fem::broadcast(bytes);
  if (fem::rank() != 0) Bytes(bytes).get(cell_rank);
  return cell_rank;
}

namespace {

// The values of `fields` at the given cells and points of a piece.
MeshFields piece_fields(const MeshFields& fields, const PartMesh& part) {
  const auto pick = [](const Field& f, const std::vector<Index>& at) {
    Field out{f.name, f.components, {}};
    out.values.reserve(at.size() * f.components);
    for (Index i : at)
      for (int k = 0; k < f.components; ++k)
        out.values.push_back(f.values[std::size_t(i) * f.components + k]);
    return out;
  };
  MeshFields out;
  for (const IntField& f : fields.cell_ints) {
    IntField g{f.name, {}};
    for (Index c : part.global_cells) g.values.push_back(f.values[c]);
    out.cell_ints.push_back(std::move(g));
  }
  out.cell_ints.push_back({"global_cell", part.global_cells});
  for (const Field& f : fields.cell) out.cell.push_back(pick(f, part.global_cells));
  for (const Field& f : fields.point) out.point.push_back(pick(f, part.global_points));
  // Point data are Float64; the ids are exact up to 2^53.
  Field ids{"global_point", 1, {}};
  ids.values.assign(part.global_points.begin(), part.global_points.end());
  out.point.push_back(std::move(ids));
  return out;
}

}  // namespace

void write_pieces(MeshPiece mine, const std::filesystem::path& path, int pieces) {
  std::unique_ptr<PvtuSet> set;
  std::vector<char> directory;
  fem::stage("write", [&] {
    if (fem::rank() != 0) return;
    set = std::make_unique<PvtuSet>(path);
    const std::string name = set->pieces_directory().string();
    directory.assign(name.begin(), name.end());
  });
  fem::broadcast(directory);
  fem::stage("write", [&] {
    write_pvtu_piece(mine, fem::rank(), std::string(directory.begin(), directory.end()), path);
  });
  fem::stage("write", [&] {
    if (fem::rank() == 0) set->commit(mine.fields, pieces);
  });
}

void write_piece_solution(const PolyMesh& piece, MeshFields fields, const RankPiece& numbers,
                          const std::filesystem::path& path) {
  MeshPiece mine;
  fem::stage("write", [&] {
    fields.cell_ints.push_back(
        {"global_cell", {numbers.global_cells.begin(), numbers.global_cells.end()}});
    // Point data are Float64; the ids are exact up to 2^53.
    fields.point.push_back(
        {"global_point", 1, {numbers.global_points.begin(), numbers.global_points.end()}});
    mine = {piece, std::move(fields)};
  });
  write_pieces(std::move(mine), path, fem::ranks());
}

void write_solution(const PolyMesh& mesh, const MeshFields& fields,
                    const std::vector<Index>& cell_rank, const std::filesystem::path& path) {
  if (path.extension() != ".pvtu") {
    fem::stage("write", [&] {
      if (fem::rank() == 0) write_mesh(mesh, path, fields);
    });
    return;
  }
  const int ranks = cell_rank.empty() ? 1 : fem::ranks();
  const std::vector<Index> one_part(cell_rank.empty() ? mesh.num_cells() : 0, 0);
  const std::vector<Index>& parts = cell_rank.empty() ? one_part : cell_rank;
  MeshPiece piece;
  fem::stage("write", [&] {
    std::vector<PartMesh> split = split_mesh(mesh, parts, ranks);
    PartMesh& mine = split[fem::rank()];
    piece = {std::move(mine.mesh), piece_fields(fields, mine)};
  });
  write_pieces(std::move(piece), path, ranks);
}

namespace {
std::vector<std::string>& command_line() {
  static std::vector<std::string> words;
  return words;
}
}  // namespace

void remember_command_line(int argc, char** argv) { command_line().assign(argv, argv + argc); }

int relaunch_under_mpirun(int ranks) {
  if (!fem::petsc_built())
    throw InputError("--np: this volmesh was built without PETSc and MPI; it runs on one process");
  // The executable by its path: /proc/self/exe would name mpirun once it runs.
  std::error_code ec;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  if (ec) throw InputError("--np: cannot find the volmesh executable (" + ec.message() + ")");
  std::vector<std::string> words{"mpirun", "--oversubscribe", "-np", std::to_string(ranks)};
  if (::geteuid() == 0) words.insert(words.begin() + 1, "--allow-run-as-root");
  words.push_back(self);
  const std::vector<std::string>& own = command_line();
  for (std::size_t i = 1; i < own.size(); ++i) {
    if (own[i] == "--np") {
      ++i;  // and its value
      continue;
    }
    if (own[i].starts_with("--np=")) continue;
    words.push_back(own[i]);
  }
  for (const std::string& w : fem::petsc_arguments()) words.push_back(w);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::cout.flush();
  const pid_t child = ::fork();
  if (child < 0) throw InputError("--np: cannot start mpirun (fork failed)");
  if (child == 0) {
    ::execvp(argv[0], argv.data());
    std::cerr << "volmesh: error: --np: cannot run mpirun (install openmpi-bin)\n";
    ::_exit(1);
  }
  int status = 0;
  if (::waitpid(child, &status, 0) < 0) throw InputError("--np: lost mpirun");
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace volmesh::cli
