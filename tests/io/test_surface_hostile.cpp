// Hostile input: cut short or corrupted fixtures, and headers claiming absurd counts, end in an
// InputError or a correct surface: never a crash, a hang, another exception or a huge
// allocation (run under ASan+UBSan with VOLMESH_SANITIZE=ON).
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <optional>
#include <random>
#include <stdexcept>

#include "../support/surfaces.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/surface_io.hpp"
#include "writer_fixtures.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::input_error_of;

const char* const kFixtures[] = {"cube_quads.off", "tetra_colour.off",      "cube.obj",
                                 "cube_ascii.stl", "cube_solid_header.stl", "cube_le.ply",
                                 "cube_be.ply",    "tetra_ascii.ply"};

// An in-memory file with a path the readers can open: thousands of variants are read here,
// and writing them to disk would dominate the run time.
class MemoryFile {
 public:
  MemoryFile() : fd_(::memfd_create("volmesh-surface", 0)) {}
  ~MemoryFile() { ::close(fd_); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  fs::path write(const std::string& bytes) {
    if (::ftruncate(fd_, 0) != 0 ||
        ::pwrite(fd_, bytes.data(), bytes.size(), 0) != static_cast<ssize_t>(bytes.size()))
      throw std::runtime_error("cannot write the memory file");
    return "/proc/self/fd/" + std::to_string(fd_);
  }

 private:
  int fd_;
};

// The path has no extension: the reader is chosen from the fixture's name.
TriSurface read_as(const std::string& name, const fs::path& path) {
  const std::string ext = fs::path(name).extension().string();
  if (ext == ".stl") return read_stl(path);
  if (ext == ".off") return read_off(path);
  if (ext == ".obj") return read_obj(path);
  return read_ply(path);
}

// Reads and checks; InputError is the only acceptable failure.
std::optional<SurfaceReport> load(const std::string& name, const fs::path& path) {
  try {
    TriSurface s = read_as(name, path);
    return check_surface(s, path.string(), {.find_self_intersections = false});
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// Truncation never yields a different valid solid: a prefix is refused unless it lost only
// trailing blanks or ignored fields.
TEST(HostileSurfaceInput, EveryPrefixIsRefusedOrReadsWhole) {
  MemoryFile file;
  for (const char* name : kFixtures) {
    SCOPED_TRACE(name);
    const std::string bytes = test::read_text(test::surface_fixture(name));
    const SurfaceReport whole = *load(name, test::surface_fixture(name));
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      if (auto report = load(name, file.write(bytes.substr(0, n)))) {
        EXPECT_EQ(report->triangles, whole.triangles) << n << " bytes";
        EXPECT_EQ(report->volume, whole.volume) << n << " bytes";
      }
    }
  }
}

TEST(HostileSurfaceInput, CorruptedBytesGiveInputErrorsOnly) {
  MemoryFile file;
  std::mt19937 random(12345);
  const char garbage[] = {'\0', '\xff', '\x80', '9', '-', ' ', '\n', '#', '/', 'e', '.'};
  for (const char* name : kFixtures) {
    SCOPED_TRACE(name);
    const std::string bytes = test::read_text(test::surface_fixture(name));
    for (int trial = 0; trial < 300; ++trial) {
      std::string corrupted = bytes;
      for (int k = 0; k < 1 + trial % 4; ++k)
        corrupted[random() % corrupted.size()] = garbage[random() % sizeof garbage];
      load(name, file.write(corrupted));  // must not crash or throw anything but InputError
    }
  }
}

// Counts just within the index limit but far beyond what the file holds are refused before
// anything is allocated for them.
TEST(HostileSurfaceInput, PlausibleLookingHugeCountsAreRefusedBeforeAllocating) {
  MemoryFile file;
  struct Case {
    const char* name;
    std::string bytes;
    const char* message;
  };
  const std::string ply_header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\n";
  const Case cases[] = {
      {"a.off", "OFF 2147483647 2147483647 0\n0 0 0\n", "more than the remaining"},
      {"b.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n2147483647 0 1 2 0 1 2\n",
       "face 0 (line 5): expected 2147483647 vertex indices, found 6"},
      {"c.ply",
       ply_header + "element face 2000000000\nproperty list uint int vertex_indices\nend_header\n",
       "more than the remaining"},
      {"d.ply",
       ply_header + "element face 1\nproperty list uint int vertex_indices\nend_header\n" +
           std::string(36, '\0') + "\xff\xff\xff\xff" + std::string(12, '\0'),
       "face 0: unexpected end of data"},
      {"e.ply",
       ply_header +
           "element face 1\nproperty list uint int vertex_indices\n"
           "property list uint double junk\nend_header\n" +
           std::string(36, '\0') + std::string("\x03\0\0\0", 4) + std::string(12, '\0') +
           "\xff\xff\xff\x7f",
       "face 0: unexpected end of data"},
      {"f.stl", "solid x\n" + std::string(200, ' '),
       "expected 'facet' or 'endsolid', found the end of the file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path path = file.write(c.bytes);
    const std::string message = input_error_of([&] { read_as(c.name, path); });
    EXPECT_NE(message.find(c.message), std::string::npos) << message;
  }
  // An element without properties holds no data, whatever its count.
  const fs::path empty_elements =
      file.write(ply_header + "element nothing 2147483647\nend_header\n" + std::string(36, '\0'));
  EXPECT_EQ(read_ply(empty_elements).num_points(), 3);
}

}  // namespace
}  // namespace volmesh
