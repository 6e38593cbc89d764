#pragma once
// Helpers for the labelled-image, rawiv and SDF-grid tests: a temporary directory, raw file
// access, InputError checks and a synthetic two-label image.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "temp_dir.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/label_image_io.hpp"

namespace volmesh::image_test {

namespace fs = std::filesystem;

using test::TempDir;

inline std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

inline void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// f() must throw an InputError whose one-line message holds every fragment.
template <class F>
void expect_input_error(F&& f, const std::vector<std::string>& fragments) {
  try {
    f();
    ADD_FAILURE() << "no InputError; expected one mentioning '" << fragments.front() << "'";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& fragment : fragments)
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "'" << fragment << "' not in: " << message;
  }
}

// Label 1 in a ball of radius 0.4 n around the image's centre, label 2 in the concentric ball
// of radius 0.2 n, 0 elsewhere (radii in voxels, n = dims[0]).
inline std::vector<Index> two_ball_labels(const std::array<Index, 3>& dims) {
  std::vector<Index> labels;
  const Vec3 centre = 0.5 * Vec3(dims[0] - 1, dims[1] - 1, dims[2] - 1);
  for (Index k = 0; k < dims[2]; ++k)
    for (Index j = 0; j < dims[1]; ++j)
      for (Index i = 0; i < dims[0]; ++i) {
        const double r = (Vec3(i, j, k) - centre).norm() / dims[0];
        labels.push_back(r < 0.2 ? 2 : r < 0.4 ? 1 : 0);
      }
  return labels;
}

inline LabelImage two_ball_image(const std::array<Index, 3>& dims, const Vec3& spacing,
                                 const Vec3& origin) {
  return make_label_image(dims, spacing, origin, two_ball_labels(dims));
}

}  // namespace volmesh::image_test
