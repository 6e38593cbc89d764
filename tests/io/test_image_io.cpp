// Labelled images from and to .inr, .inr.gz and .nrrd files: round trips through the
// library's writers, files written by hand byte by byte, and hostile headers and data.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>

#include "../support/images.hpp"
#include "volmesh/io/label_image_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using image_test::expect_input_error;
using image_test::read_bytes;
using image_test::TempDir;
using image_test::two_ball_image;
using image_test::write_bytes;

template <class T>
void put(std::string& out, T value, bool big_endian) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

// An INRIMAGE-4 header padded, end marker included, to 256 bytes.
std::string inr_header(const std::vector<std::string>& lines) {
  std::string h = "#INRIMAGE-4#{\n";
  for (const std::string& line : lines) h += line + "\n";
  h.append(252 - h.size(), '\n');
  return h + "##}\n";
}

// Labels that exercise every voxel position: (i + 2j + 3k) mod 5, times `scale`.
Index pattern(Index i, Index j, Index k, Index scale) { return (i + 2 * j + 3 * k) % 5 * scale; }

void expect_pattern(const LabelImage& image, Index scale) {
  for (Index k = 0; k < image.dims[2]; ++k)
    for (Index j = 0; j < image.dims[1]; ++j)
      for (Index i = 0; i < image.dims[0]; ++i)
        ASSERT_EQ(image.label(i, j, k), pattern(i, j, k, scale));
}

TEST(ImageIo, RoundTripsThroughInrInrGzAndNrrd) {
  TempDir dir;
  const LabelImage image =
      two_ball_image({32, 32, 32}, Vec3(0.5, 0.75, 1.25), Vec3(-3.0, 2.0, 10.1));
  ASSERT_EQ(image.labels, (std::vector<Index>{0, 1, 2}));
  for (const std::string name : {"ball.inr", "ball.inr.gz", "ball.nrrd", "BALL.INR.GZ"}) {
    SCOPED_TRACE(name);
    write_label_image(image, dir / name);
    const LabelImage back = read_label_image(dir / name);
    EXPECT_EQ(back.dims, image.dims);
    EXPECT_EQ(back.spacing,
              image.spacing);  // exactly: numbers are written in shortest round-trip form
    EXPECT_EQ(back.origin, image.origin);
    EXPECT_EQ(back.labels, image.labels);
    EXPECT_EQ(back.codes, image.codes);
  }
  const std::string inr = read_bytes(dir / "ball.inr");
  EXPECT_EQ(inr.rfind("#INRIMAGE-4#{\nXDIM=32\n", 0), 0u);
  EXPECT_EQ(inr.size(), 256u + 32 * 32 * 32);  // one header block, one byte per voxel
  EXPECT_EQ(inr.substr(252, 4), "##}\n");
  const std::string gz = read_bytes(dir / "ball.inr.gz");
  EXPECT_EQ(gz.substr(0, 2), "\x1f\x8b");
  EXPECT_LT(gz.size(), inr.size() / 4);
  EXPECT_NE(read_bytes(dir / "ball.nrrd").find("\nencoding: gzip\n"), std::string::npos);
  EXPECT_TRUE(std::none_of(
      fs::directory_iterator(dir.path()), fs::directory_iterator(),
      [](const fs::directory_entry& e) { return e.path().filename().string()[0] == '.'; }))
      << "a temporary file was left behind";
}

TEST(ImageIo, WritesWideLabelsInWiderTypes) {
  TempDir dir;
  const std::vector<Index> labels{0, 70000, 255, 3, 1, 0, 70000, 9};
  const LabelImage image = make_label_image({2, 2, 2}, Vec3::Ones(), Vec3::Zero(), labels);
  for (const std::string name : {"wide.inr", "wide.nrrd"}) {
    write_label_image(image, dir / name);
    EXPECT_EQ(read_label_image(dir / name).codes, image.codes);
  }
  EXPECT_NE(read_bytes(dir / "wide.inr").find("TYPE=signed fixed\nPIXSIZE=32 bits\n"),
            std::string::npos);
}

TEST(ImageIo, ReadsAHandWrittenBigEndianInr) {
  TempDir dir;
  std::string file = inr_header({"XDIM=3", "YDIM=4", "ZDIM=2", "VDIM=1", "TYPE=signed fixed",
                                 "PIXSIZE=16 bits", "SCALE=2**0", "CPU=sun", "VX=0.5", "VY=2",
                                 "VZ=1.33333", "TX=-1.5", "#a comment"});
  for (Index k = 0; k < 2; ++k)
    for (Index j = 0; j < 4; ++j)
      for (Index i = 0; i < 3; ++i)
        put<std::int16_t>(file, static_cast<std::int16_t>(pattern(i, j, k, 1000)), true);
  write_bytes(dir / "hand.inr", file);
  const LabelImage image = read_label_image(dir / "hand.inr");
  EXPECT_EQ(image.dims, (std::array<Index, 3>{3, 4, 2}));
  EXPECT_EQ(image.spacing, Vec3(0.5, 2.0, 1.33333));
  EXPECT_EQ(image.origin, Vec3(-1.5, 0.0, 0.0));
  EXPECT_EQ(image.labels, (std::vector<Index>{0, 1000, 2000, 3000, 4000}));
  expect_pattern(image, 1000);
}

std::string nrrd_header(const std::string& type, const std::string& extra) {
  return "NRRD0004\n# hand-written\ntype: " + type +
         "\ndimension: 3\nspace: left-posterior-superior\nsizes: 4 3 2\n"
         "space directions: (0.25,0,0) (0, 0.5, 0) (0,0,2)\nkinds: domain domain domain\n"
         "space origin: (1,-2,3.5)\ncustom:=value: ignored\n" +
         extra + "\n";
}

template <class T>
std::string pattern_data(bool big_endian) {
  std::string data;
  for (Index k = 0; k < 2; ++k)
    for (Index j = 0; j < 3; ++j)
      for (Index i = 0; i < 4; ++i) put<T>(data, static_cast<T>(pattern(i, j, k, 3)), big_endian);
  return data;
}

TEST(ImageIo, ReadsRawNrrdOfEverySampleType) {
  TempDir dir;
  const auto check = [&](const std::string& type, const std::string& data,
                         const std::string& endian) {
    SCOPED_TRACE(type + " " + endian);
    write_bytes(dir / "t.nrrd",
                nrrd_header(type, "endian: " + endian + "\nencoding: raw\n") + data);
    const LabelImage image = read_label_image(dir / "t.nrrd");
    EXPECT_EQ(image.dims, (std::array<Index, 3>{4, 3, 2}));
    EXPECT_EQ(image.spacing, Vec3(0.25, 0.5, 2.0));
    EXPECT_EQ(image.origin, Vec3(1.0, -2.0, 3.5));
    expect_pattern(image, 3);
  };
  check("uchar", pattern_data<std::uint8_t>(false), "little");
  check("unsigned char", pattern_data<std::uint8_t>(false), "little");
  check("ushort", pattern_data<std::uint16_t>(true), "big");
  check("short", pattern_data<std::int16_t>(false), "little");
  check("int", pattern_data<std::int32_t>(true), "big");
  check("uint32", pattern_data<std::uint32_t>(false), "little");
  check("float", pattern_data<float>(false), "little");
  check("double", pattern_data<double>(true), "big");
}

TEST(ImageIo, ReadsNrrdWithSpacingsInsteadOfSpaceDirections) {
  TempDir dir;
  const std::string header =
      "NRRD0001\ntype: uint8\ndimension: 3\nsizes: 4 3 2\nspacings: 0.25 0.5 2\nencoding: raw\n\n";
  write_bytes(dir / "s.nrrd", header + pattern_data<std::uint8_t>(false));
  const LabelImage image = read_label_image(dir / "s.nrrd");
  EXPECT_EQ(image.spacing, Vec3(0.25, 0.5, 2.0));
  EXPECT_EQ(image.origin, Vec3::Zero());
  expect_pattern(image, 3);
}

TEST(ImageIo, RejectsBadInrHeaders) {
  TempDir dir;
  const std::vector<std::string> good{"XDIM=2",         "YDIM=2",  "ZDIM=2", "TYPE=unsigned fixed",
                                      "PIXSIZE=8 bits", "CPU=decm"};
  const auto check = [&](std::vector<std::string> lines, const std::string& data,
                         const std::vector<std::string>& fragments) {
    SCOPED_TRACE(fragments.front());
    const fs::path path = dir / "bad.inr";
    write_bytes(path, inr_header(lines) + data);
    std::vector<std::string> expected = fragments;
    expected.push_back(path.string() + ": ");
    expect_input_error([&] { read_label_image(path); }, expected);
  };
  const std::string eight(8, '\1');
  auto with = [&](std::string line) {
    std::vector<std::string> lines = good;
    lines.push_back(std::move(line));
    return lines;
  };
  check(with("VX=0"), eight, {"VX: spacing 0"});
  check(with("VY=-0.5"), eight, {"VY: spacing -0.5"});
  check(with("VZ=nan"), eight, {"VZ: spacing nan"});
  check(with("VDIM=3"), eight, {"VDIM=3", "vector"});
  check({"XDIM=100000", "YDIM=100000", "ZDIM=100000", "TYPE=unsigned fixed", "PIXSIZE=8 bits"},
        eight, {"XDIM/YDIM/ZDIM", "100000 x 100000 x 100000", "more than"});
  check({"XDIM=9223372036854775807", "YDIM=9223372036854775807", "ZDIM=2", "TYPE=float",
         "PIXSIZE=32 bits", "CPU=pc"},
        eight, {"XDIM/YDIM/ZDIM", "more than"});
  check({"XDIM=0", "YDIM=2", "ZDIM=2", "TYPE=unsigned fixed", "PIXSIZE=8 bits"}, eight,
        {"XDIM/YDIM/ZDIM", "0 samples"});
  check({"XDIM=2", "YDIM=2", "TYPE=unsigned fixed", "PIXSIZE=8 bits"}, eight, {"ZDIM missing"});
  check({"XDIM=2", "YDIM=2", "ZDIM=2x", "TYPE=unsigned fixed", "PIXSIZE=8 bits"}, eight,
        {"ZDIM=2x", "not an integer"});
  check({"XDIM=2", "YDIM=2", "ZDIM=2", "TYPE=unsigned fixed", "PIXSIZE=12 bits"}, eight,
        {"PIXSIZE=12 bits"});
  check({"XDIM=2", "YDIM=2", "ZDIM=2", "TYPE=signed fixed", "PIXSIZE=16 bits"}, eight + eight,
        {"CPU missing"});
  check(with("CPU=vax"), eight, {"CPU=vax"});
  check(good, eight.substr(3), {"truncated", "5 bytes", "8 bytes"});
  check(good, eight + "x", {"data:", "8 bytes"});
  check({"XDIM=2", "YDIM=2", "ZDIM=2", "TYPE=signed fixed", "PIXSIZE=8 bits"},
        std::string(7, '\1') + "\xff", {"voxel (1, 1, 1)", "value -1", "not a label"});
  check({"XDIM=2", "YDIM=2", "ZDIM=2", "TYPE=float", "PIXSIZE=32 bits", "CPU=decm"},
        [] {
          std::string d;
          for (int v = 0; v < 8; ++v) put<float>(d, v == 5 ? 1.5f : 1.0f, false);
          return d;
        }(),
        {"voxel (1, 0, 1)", "value 1.5", "not a label"});

  write_bytes(dir / "nomagic.inr", std::string(300, 'x'));
  expect_input_error([&] { read_label_image(dir / "nomagic.inr"); },
                     {"nomagic.inr: ", "INRIMAGE-4"});
  write_bytes(dir / "noend.inr", "#INRIMAGE-4#{\nXDIM=2\n" + std::string(100, '\n'));
  expect_input_error([&] { read_label_image(dir / "noend.inr"); }, {"noend.inr: ", "##}"});
  expect_input_error([&] { read_label_image(dir / "missing.inr"); },
                     {"missing.inr: ", "cannot open"});
  expect_input_error([&] { read_label_image(dir / "image.png"); }, {"image.png: ", ".inr"});
}

TEST(ImageIo, RejectsTruncatedAndCorruptGzip) {
  TempDir dir;
  const LabelImage image = two_ball_image({32, 32, 32}, Vec3::Ones(), Vec3::Zero());
  write_label_image(image, dir / "ball.inr.gz");
  write_label_image(image, dir / "ball.nrrd");
  const std::string gz = read_bytes(dir / "ball.inr.gz");
  write_bytes(dir / "half.inr.gz", gz.substr(0, gz.size() / 2));
  expect_input_error([&] { read_label_image(dir / "half.inr.gz"); },
                     {"half.inr.gz: ", "truncated", "32768 bytes"});
  write_bytes(dir / "header.inr.gz", gz.substr(0, 20));
  expect_input_error([&] { read_label_image(dir / "header.inr.gz"); }, {"header.inr.gz: "});
  std::string corrupt = gz;
  for (std::size_t b = 20; b < 60; ++b) corrupt[b] = static_cast<char>(corrupt[b] ^ 0x5a);
  write_bytes(dir / "corrupt.inr.gz", corrupt);
  expect_input_error([&] { read_label_image(dir / "corrupt.inr.gz"); }, {"corrupt.inr.gz: "});
  const std::string nrrd = read_bytes(dir / "ball.nrrd");
  write_bytes(dir / "half.nrrd", nrrd.substr(0, nrrd.size() - 40));
  expect_input_error([&] { read_label_image(dir / "half.nrrd"); }, {"half.nrrd: ", "truncated"});
}

TEST(ImageIo, RejectsBadNrrdHeaders) {
  TempDir dir;
  const std::string data = pattern_data<std::uint8_t>(false);
  const auto check = [&](const std::string& header, const std::vector<std::string>& fragments) {
    SCOPED_TRACE(fragments.front());
    write_bytes(dir / "bad.nrrd", header + data);
    std::vector<std::string> expected = fragments;
    expected.push_back((dir / "bad.nrrd").string() + ": ");
    expect_input_error([&] { read_label_image(dir / "bad.nrrd"); }, expected);
  };
  const auto header = [](const std::string& directions,
                         const std::string& more = "encoding: raw\n") {
    return "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nspace directions: " + directions +
           "\n" + more + "\n";
  };
  check(header("(0,0,0) (0,1,0) (0,0,1)"), {"space directions x: spacing 0"});
  check(header("(1,0,0) (0,-1,0) (0,0,1)"), {"space directions y: spacing -1"});
  check(header("(1,0,0) (0,1,0.5) (0,0,1)"), {"space directions", "not along axis y"});
  check(header("(1,0,0) (0,1,0)"), {"space directions", "not a vector"});
  check(header("(1,0,0) (0,1,0) (0,0,1)", "encoding: ascii\n"), {"encoding: ascii"});
  check(header("(1,0,0) (0,1,0) (0,0,1)", "encoding: raw\ndata file: other.raw\n"),
        {"data file", "detached"});
  check(header("(1,0,0) (0,1,0) (0,0,1)", ""), {"'encoding' missing"});
  check("NRRD0004\ntype: longlong\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nendian: little\n\n",
        {"type: longlong"});
  check("NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n\n",
        {"'endian' missing"});
  check("NRRD0004\ntype: uchar\ndimension: 4\nsizes: 1 4 3 2\nencoding: raw\n\n", {"dimension: 4"});
  check("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3\nencoding: raw\n\n", {"sizes: 4 3"});
  check("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 70000 70000 70000\nencoding: gzip\n\n",
        {"sizes", "more than"});
  check("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nspace origin: (1,2)\nencoding: raw\n\n",
        {"space origin", "not a vector"});
  write_bytes(dir / "short.nrrd", "NRRD0004\ntype: uchar\n");
  expect_input_error([&] { read_label_image(dir / "short.nrrd"); }, {"short.nrrd: ", "blank line"});
}

TEST(ImageIo, MakeLabelImageChecksItsInput) {
  const std::vector<Index> labels{0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_EQ(make_label_image({2, 2, 2}, Vec3::Ones(), Vec3::Zero(), labels).labels, labels);
  EXPECT_THROW(make_label_image({2, 2, 3}, Vec3::Ones(), Vec3::Zero(), labels), InputError);
  EXPECT_THROW(make_label_image({2, 2, 2}, Vec3(1, 0, 1), Vec3::Zero(), labels), InputError);
  const std::vector<Index> negative{0, 1, 2, -3, 4, 5, 6, 7};
  expect_input_error(
      [&] {
        make_label_image({2, 2, 2}, Vec3::Ones(), Vec3::Zero(), negative);
      },
      {"voxel (1, 1, 0)", "-3"});
  std::vector<Index> many(70000);
  for (std::size_t v = 0; v < many.size(); ++v) many[v] = static_cast<Index>(v);
  expect_input_error(
      [&] {
        make_label_image({70000, 1, 1}, Vec3::Ones(), Vec3::Zero(), many);
      },
      {"65536"});
  // No voxel with label 0: code 0 still means 0, the outside.
  const LabelImage full =
      make_label_image({1, 1, 2}, Vec3::Ones(), Vec3::Zero(), std::vector<Index>{4, 9});
  EXPECT_EQ(full.labels, (std::vector<Index>{0, 4, 9}));
  EXPECT_EQ(full.codes, (std::vector<std::uint16_t>{1, 2}));
}

}  // namespace
}  // namespace volmesh
