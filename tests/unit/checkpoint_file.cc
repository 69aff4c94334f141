// The checkpoint file (io/checkpoint_file.h): arrays of doubles (bit for
// bit, including -0, denormals and infinities), unsigned ints, strings,
// deal.II tensors and empty arrays read back exactly; the name carries the
// hash of the bytes, and a file truncated or with one byte changed is
// refused with a message (never read); a missing entry is named.

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <fsgmpm/io/checkpoint_file.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

using namespace dealii;
using namespace fsgmpm;

namespace
{
  std::string
  message_of(const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        return info.str();
      }
    return "";
  }

  struct Directory
  {
    Directory()
      : path(std::filesystem::temp_directory_path()
             / ("fsgmpm_checkpoint_" + std::to_string(::getpid())))
    {
      std::filesystem::create_directories(path);
    }
    ~Directory()
    {
      std::filesystem::remove_all(path);
    }
    std::filesystem::path path;
  };

  std::string
  write_example(const std::string &stem)
  {
    CheckpointWriter out(stem);
    out.put("a/doubles",
            std::vector<double>{1.0 / 3.0,
                                -0.0,
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::infinity(),
                                -1e308});
    out.put("a/uints", std::vector<unsigned int>{0u, 7u, 4294967295u});
    out.put("empty", std::vector<double>{});
    out.put("text", std::string("Simulation/End time = 1\n"));
    out.put_tensors("points",
                    std::vector<Point<2>>{Point<2>(1, 2), Point<2>(-3, 0.5)});
    SymmetricTensor<2, 3> s;
    s[0][1] = 2.5;
    s[2][2] = -1;
    out.put_tensors("stress", std::vector<SymmetricTensor<2, 3>>{s});
    out.put_integers("ids", std::vector<std::uint16_t>{65535, 3});
    return out.commit();
  }
} // namespace

TEST(CheckpointFile, RoundTripBitForBit)
{
  Directory         dir;
  const std::string file = write_example((dir.path / "c_0000000001").string());
  EXPECT_FALSE(std::filesystem::exists(dir.path / "c_0000000001.h5.tmp"));
  const CheckpointReader    in(file);
  const auto               &d = in.doubles("a/doubles");
  const std::vector<double> expected
    = {1.0 / 3.0,
       -0.0,
       std::numeric_limits<double>::denorm_min(),
       std::numeric_limits<double>::infinity(),
       -1e308};
  ASSERT_EQ(d.size(), expected.size());
  EXPECT_EQ(std::memcmp(d.data(), expected.data(), d.size() * sizeof(double)),
            0);
  EXPECT_EQ(in.uints("a/uints"),
            (std::vector<unsigned int>{0u, 7u, 4294967295u}));
  EXPECT_TRUE(in.doubles("empty").empty());
  EXPECT_EQ(in.text("text"), "Simulation/End time = 1\n");
  const auto points = in.tensors<Point<2>>("points");
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1], Point<2>(-3, 0.5));
  const auto stress = in.tensors<SymmetricTensor<2, 3>>("stress");
  EXPECT_EQ(stress[0][1][0], 2.5);
  EXPECT_EQ(stress[0][2][2], -1.);
  EXPECT_EQ(in.integers<std::uint16_t>("ids"),
            (std::vector<std::uint16_t>{65535, 3}));
  EXPECT_NE(message_of([&] {
              in.doubles("missing");
            }).find("no entry <missing>"),
            std::string::npos);
}

TEST(CheckpointFile, DamagedFilesAreRefused)
{
  Directory         dir;
  const std::string file = write_example((dir.path / "c_0000000002").string());
  const auto        size = std::filesystem::file_size(file);

  // One byte changed in the middle.
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(size / 2);
    char c;
    f.get(c);
    f.seekp(size / 2);
    f.put(char(c ^ 1));
  }
  EXPECT_NE(message_of([&] {
              CheckpointReader in(file);
            }).find("it is damaged"),
            std::string::npos);

  // Truncated.
  const std::string file2 = write_example((dir.path / "c_0000000003").string());
  std::filesystem::resize_file(file2, std::filesystem::file_size(file2) / 2);
  EXPECT_NE(message_of([&] {
              CheckpointReader in(file2);
            }).find("it is damaged"),
            std::string::npos);

  // Not a checkpoint's name.
  EXPECT_NE(message_of([&] {
              CheckpointReader in((dir.path / "x").string());
            }).find("not named as an fsgmpm checkpoint"),
            std::string::npos);
}

// Tables of rows (put_rows: the material points, split over the processes
// with MPI): a serial reader gets every row back, bit for bit; an unused
// table (no rows anywhere) is listed empty; a table with another number of
// rows than the first is refused when written, and the partial file goes.
TEST(CheckpointFile, RowTablesRoundTrip)
{
  Directory   dir;
  std::string file;
  {
    CheckpointWriter out((dir.path / "c_0000000004").string());
    out.put_tensor_rows("position",
                        std::vector<Point<2>>{Point<2>(1, 2),
                                              Point<2>(-0.0, 1e-310),
                                              Point<2>(5, 6)});
    out.put_rows("mass", std::vector<double>{0.5, 0.25, 0.125});
    out.put_integer_rows("flag", std::vector<std::uint8_t>{0, 1, 255});
    out.put_tensor_rows("affine", std::vector<Tensor<2, 2>>{});
    file = out.commit();
  }
  {
    CheckpointWriter bad((dir.path / "c_0000000005").string());
    bad.put_rows("mass", std::vector<double>{0.5, 0.25, 0.125});
    EXPECT_NE(message_of([&] {
                bad.put_rows("wrong", std::vector<double>{1, 2});
              }).find("other rows per process"),
              std::string::npos);
    // The writer closed and removed its file, and says so if used again.
    EXPECT_FALSE(std::filesystem::exists(dir.path / "c_0000000005.h5.tmp"));
    EXPECT_NE(message_of([&] { bad.commit(); }).find("failed before"),
              std::string::npos);
  }
  const CheckpointReader in(file);
  EXPECT_FALSE(in.rows_split());
  const auto position = in.tensors<Point<2>>("position");
  ASSERT_EQ(position.size(), 3u);
  EXPECT_EQ(position[1][1], 1e-310);
  EXPECT_TRUE(std::signbit(position[1][0]));
  EXPECT_EQ(in.doubles("mass"), (std::vector<double>{0.5, 0.25, 0.125}));
  EXPECT_EQ(in.integers<std::uint8_t>("flag"),
            (std::vector<std::uint8_t>{0, 1, 255}));
  EXPECT_TRUE(in.doubles("affine").empty());
  EXPECT_EQ(in.uints("checkpoint/rows_per_process"),
            (std::vector<unsigned int>{3}));
}
