// Tests of reading point files (lib/src/sampling/point_file.cpp): CSV with and without its
// header and .npy (float64, float32, versions 1.0 and 2.0) read back bitwise; every bad file
// refused with one line naming the file (and the row and column of a bad value); the path
// template; file_points as a point set.
#include "quadmc/sampling/point_file.hpp"
#include "quadmc/core/errors.hpp"
#include "support/temporary_directory.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace quadmc {
namespace {

namespace fs = std::filesystem;
using test_support::temporary_directory;

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// A .npy file as NumPy writes it: magic, version, header length, a dict padded with spaces to a
// multiple of 64 bytes and ended by '\n', then the raw little-endian data.
std::string npy_bytes(const std::string& dict, const std::string& data, int major = 1) {
  const std::size_t prefix = major == 1 ? 10 : 12;
  std::string header = dict;
  while ((prefix + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string out("\x93NUMPY", 6);
  out += static_cast<char>(major);
  out += '\0';
  for (std::size_t k = 0; k < prefix - 8; ++k) {
    out += static_cast<char>((header.size() >> (8 * k)) & 0xff);
  }
  return out + header + data;
}

template <class T>
std::string raw(const std::vector<T>& values) {
  std::string out(values.size() * sizeof(T), '\0');
  std::memcpy(out.data(), values.data(), out.size());  // x86-64: little-endian already
  return out;
}

std::string shape_dict(std::string_view descr, std::uint64_t n, std::uint64_t c) {
  return fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': ({}, {}), }}", descr, n, c);
}

// The message of read_point_file's refusal, or "no error"; it must be one line.
std::string refusal(const fs::path& file, point_file_columns columns = point_file_columns::points,
                    std::uint64_t n = 0, std::size_t s = 0) {
  try {
    read_point_file(file, columns, n, s);
  } catch (const invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    return message;
  }
  return "no error";
}

bool has(const std::string& text, std::string_view part) {
  return text.find(part) != std::string::npos;
}

const std::vector<double> some_points = {0.0,       0.5,  0.1 + 0.2,
                                         1.0 / 3.0, 0.75, 0x1.fffffffffffffp-1};

TEST(PointFile, CsvWithOrWithoutHeaderReadsBackBitwise) {
  const temporary_directory dir("point_file_csv", temporary_directory::start::empty);
  std::string body;
  for (std::size_t i = 0; i < 3; ++i) {
    body += fmt::format("{},{}\n", some_points[2 * i], some_points[2 * i + 1]);
  }
  write_text(dir.path / "with.csv", "x1,x2\n" + body);
  write_text(dir.path / "without.csv", body);
  for (const char* name : {"with.csv", "without.csv"}) {
    const point_file_data d = read_point_file(dir.path / name, point_file_columns::points, 3, 2);
    EXPECT_EQ(d.n, 3u);
    EXPECT_EQ(d.s, 2u);
    EXPECT_TRUE(d.w.empty());
    ASSERT_EQ(d.x.size(), some_points.size());
    for (std::size_t k = 0; k < d.x.size(); ++k) EXPECT_EQ(d.x[k], some_points[k]) << name << k;
  }
  write_text(dir.path / "rule.csv", "x1,w\n0,-0.5\n1,1.5\r\n");
  const point_file_data r =
      read_point_file(dir.path / "rule.csv", point_file_columns::points_and_weights);
  EXPECT_EQ(r.s, 1u);
  EXPECT_EQ(r.x, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(r.w, (std::vector<double>{-0.5, 1.5}));
}

TEST(PointFile, NpyFloat64AndFloat32VersionsOneAndTwo) {
  const temporary_directory dir("point_file_npy", temporary_directory::start::empty);
  write_text(dir.path / "a.npy", npy_bytes(shape_dict("<f8", 3, 2), raw(some_points)));
  write_text(dir.path / "b.npy", npy_bytes(shape_dict("<f8", 3, 2), raw(some_points), 2));
  for (const char* name : {"a.npy", "b.npy"}) {
    const point_file_data d = read_point_file(dir.path / name, point_file_columns::points, 3, 2);
    EXPECT_EQ(d.x, some_points) << name;
  }
  const std::vector<float> f32 = {0.25f, 0.1f, 0.999f, 0.0f};
  write_text(dir.path / "c.npy", npy_bytes(shape_dict("<f4", 2, 2), raw(f32)));
  const point_file_data d = read_point_file(dir.path / "c.npy", point_file_columns::points);
  ASSERT_EQ(d.x.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(d.x[k], static_cast<double>(f32[k]));
}

TEST(PointFile, EveryBadFileIsRefusedWithOneLineNamingIt) {
  const temporary_directory dir("point_file_bad", temporary_directory::start::empty);
  const fs::path p = dir.path;
  EXPECT_TRUE(has(refusal(p / "missing.csv"), "missing")) << refusal(p / "missing.csv");
  fs::create_directories(p / "folder.csv");
  EXPECT_TRUE(has(refusal(p / "folder.csv"), "not a regular file"));
  {
    std::ofstream(p / "huge.csv").put('0');
    fs::resize_file(p / "huge.csv", max_point_file_bytes + 1);  // sparse: nothing is written
    EXPECT_TRUE(has(refusal(p / "huge.csv"), "max_point_file_bytes"));
  }
  write_text(p / "n.csv", "0.1,0.2\n0.3,0.4\n");
  EXPECT_TRUE(has(refusal(p / "n.csv", point_file_columns::points, 4, 2), "N = 4 rows"));
  EXPECT_TRUE(has(refusal(p / "n.csv", point_file_columns::points, 2, 3), "s = 3"));
  write_text(p / "ragged.csv", "0.1,0.2\n0.3\n");
  EXPECT_TRUE(has(refusal(p / "ragged.csv"), "row 2 column 2"));
  write_text(p / "text.csv", "0.1,0.2\n0.3,abc\n");
  const std::string text = refusal(p / "text.csv");
  EXPECT_TRUE(has(text, "row 2 column 2") && has(text, "'abc'")) << text;
  write_text(p / "one.csv", "x1,x2\n0.1,0.2\n0.3,1\n");
  const std::string one = refusal(p / "one.csv");
  EXPECT_TRUE(has(one, "row 2 column 2") && has(one, "[0, 1)")) << one;
  write_text(p / "neg.csv", "-0.5,0.2\n");
  EXPECT_TRUE(has(refusal(p / "neg.csv"), "row 1 column 1"));
  write_text(p / "nan.csv", "0.5,nan\n");
  EXPECT_TRUE(has(refusal(p / "nan.csv"), "a finite coordinate"));
  write_text(p / "weight.csv", "0.5,1\n0.25,inf\n");
  const std::string w = refusal(p / "weight.csv", point_file_columns::points_and_weights);
  EXPECT_TRUE(has(w, "row 2 column 2") && has(w, "a finite weight")) << w;
  write_text(p / "empty.csv", "x1\n");
  EXPECT_TRUE(has(refusal(p / "empty.csv"), "no data rows"));

  const std::string data = raw(some_points);
  auto npy = [&](const std::string& name, const std::string& bytes) {
    write_text(p / name, bytes);
    return refusal(p / name, point_file_columns::points, 3, 2);
  };
  EXPECT_TRUE(has(npy("magic.npy", "NUMPY" + data), "magic"));
  std::string v4 = npy_bytes(shape_dict("<f8", 3, 2), data);
  v4[6] = 4;
  EXPECT_TRUE(has(npy("v4.npy", v4), "version 4.0"));
  EXPECT_TRUE(has(npy("i8.npy", npy_bytes(shape_dict("<i8", 3, 2), data)), "dtype '<i8'"));
  EXPECT_TRUE(has(npy("big.npy", npy_bytes(shape_dict(">f8", 3, 2), data)), "dtype '>f8'"));
  EXPECT_TRUE(
      has(npy("fortran.npy",
              npy_bytes("{'descr': '<f8', 'fortran_order': True, 'shape': (3, 2), }", data)),
          "fortran_order"));
  EXPECT_TRUE(has(npy("shape1.npy",
                      npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': (6,), }", data)),
                  "shape of 1 dimensions"));
  EXPECT_TRUE(has(npy("cols.npy", npy_bytes(shape_dict("<f8", 2, 3), data)), "3 columns"));
  EXPECT_TRUE(has(npy("rows.npy", npy_bytes(shape_dict("<f8", 6, 1), data)), "1 columns"));
  EXPECT_TRUE(
      has(npy("short.npy", npy_bytes(shape_dict("<f8", 3, 2), data.substr(8))), "bytes of data"));
  EXPECT_TRUE(has(npy("key.npy", npy_bytes("{'descr': '<f8', 'fortran_order': False, 'shape': "
                                           "(3, 2), 'extra': 1}",
                                           data)),
                  "key 'extra'"));
  EXPECT_TRUE(has(npy("nokey.npy", npy_bytes("{'descr': '<f8', 'shape': (3, 2)}", data)),
                  "without 'descr', 'fortran_order' or 'shape'"));
  std::vector<double> bad = some_points;
  bad[3] = 1.5;
  const std::string value = npy("value.npy", npy_bytes(shape_dict("<f8", 3, 2), raw(bad)));
  EXPECT_TRUE(has(value, "row 2 column 2") && has(value, "[0, 1)")) << value;
  bad[3] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(has(npy("inf.npy", npy_bytes(shape_dict("<f8", 3, 2), raw(bad))), "row 2 column 2"));
}

TEST(PointFile, PathTemplateReplacesNAndRAndResolvesRelativePaths) {
  EXPECT_EQ(point_file_path("s/{N}_{r}.csv", 64, 3), fs::path("s/64_3.csv"));
  EXPECT_EQ(point_file_path("s/{N}_{r}.csv", 64, 3, "scenes"), fs::path("scenes/s/64_3.csv"));
  EXPECT_EQ(point_file_path("/abs/{r}-{N}.npy", 8, 0, "scenes"), fs::path("/abs/0-8.npy"));
}

TEST(PointFile, FilePointsCopyRowsAndHaveNoOwnErrorEstimate) {
  point_file_data d;
  d.s = 2;
  d.n = 3;
  d.x = some_points;
  const file_points points(d);
  static_assert(point_set<file_points>);
  EXPECT_EQ(points.variance().kind, variance_kind::not_estimable);
  std::vector<double> out(4);
  points.generate(1, out);
  EXPECT_EQ(out, (std::vector<double>(some_points.begin() + 2, some_points.end())));
  std::vector<double> past(4);
  EXPECT_THROW(points.generate(2, past), invalid_argument);
}

}  // namespace
}  // namespace quadmc
