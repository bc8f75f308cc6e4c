#include "encode/png_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "core/error.h"

namespace cablefilm {
namespace {

std::string TempDir() {
  const auto dir = std::filesystem::path(CABLEFILM_BINARY_DIR) / "test_output" / "encode";
  std::filesystem::create_directories(dir);
  return dir.string();
}

Image RandomImage(int w, int h, bool opaque, unsigned seed) {
  Image image(w, h);
  std::mt19937 rng(seed);
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = (opaque && i % 4 == 3) ? 255 : static_cast<std::uint8_t>(rng() & 0xff);
  return image;
}

// PNG is lossless: every byte must come back, exactly.
TEST(PngWriter, RgbRoundTripIsExact) {
  const Image image = RandomImage(37, 21, /*opaque=*/true, 1);  // odd sizes: no row padding
  const std::string path = TempDir() + "/rgb.png";
  WritePng(path, image);
  const Image back = ReadPng(path);
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 21);
  EXPECT_EQ(back.rgba, image.rgba);
}

TEST(PngWriter, RgbaRoundTripKeepsAlpha) {
  const Image image = RandomImage(16, 9, /*opaque=*/false, 2);
  const std::string path = TempDir() + "/rgba.png";
  PngOptions options;
  options.keep_alpha = true;
  options.compression_level = 1;
  WritePng(path, image, options);
  EXPECT_EQ(ReadPng(path).rgba, image.rgba);
}

TEST(PngWriter, OpaqueRgbFileDropsTheAlphaByte) {
  // Written as RGB, read back with alpha 255 whatever the image's alpha was.
  Image image = RandomImage(4, 4, /*opaque=*/false, 3);
  const std::string path = TempDir() + "/dropped.png";
  WritePng(path, image);
  const Image back = ReadPng(path);
  for (std::size_t i = 0; i < back.rgba.size(); ++i)
    EXPECT_EQ(back.rgba[i], i % 4 == 3 ? 255 : image.rgba[i]) << "byte " << i;
}

// Written a band of rows at a time, the file is the one WritePng writes of the whole image.
TEST(PngWriter, RowWriterInBandsWritesTheSameFile) {
  const Image image = RandomImage(37, 21, /*opaque=*/true, 4);
  PngOptions options;
  options.compression_level = 3;
  options.up_filter_only = true;
  options.memory_level = 5;
  const std::string whole = TempDir() + "/whole.png", banded = TempDir() + "/banded.png";
  WritePng(whole, image, options);
  std::filesystem::remove(banded);  // an earlier run's
  PngRowWriter writer(banded, 37, 21, options);
  for (int y0 = 0; y0 < 21; y0 += 8) {
    Image band(37, std::min(8, 21 - y0));
    std::copy(image.row(y0), image.row(y0) + band.rgba.size(), band.rgba.begin());
    writer.Write(band);
  }
  EXPECT_FALSE(std::filesystem::exists(banded));  // not before the commit
  writer.Commit();
  auto bytes = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(banded), bytes(whole));
}

// A row writer given too many rows, or committed before its last row, throws and leaves no file.
TEST(PngWriter, RowWriterRefusesRowsThatDoNotFitAndLeavesNothing) {
  const std::string path = TempDir() + "/short.png";
  std::filesystem::remove(path);
  {
    PngRowWriter writer(path, 8, 4);
    EXPECT_THROW(writer.Write(Image(8, 5)), Error);
    writer.Write(Image(8, 3));
    EXPECT_THROW(writer.Commit(), Error);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(PngWriter, UnwritablePathThrowsAndLeavesNothing) {
  const Image image(8, 8);
  EXPECT_THROW(WritePng("/nonexistent_dir_cablefilm/x.png", image), Error);
  // A folder of its own: ctest runs the other tests in parallel, and their temporary files in
  // TempDir() must not be mistaken for leftovers of this one.
  const std::string dir = TempDir() + "/unwritable";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/never.png";
  Image bad;
  bad.width = 8;
  bad.height = 8;  // no pixels
  EXPECT_THROW(WritePng(path, bad), Error);
  EXPECT_FALSE(std::filesystem::exists(path));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(PngWriter, ReadingAMissingOrBrokenFileThrows) {
  EXPECT_THROW(ReadPng(TempDir() + "/missing.png"), Error);
  const std::string path = TempDir() + "/broken.png";
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    std::fputs("not a png at all", f);
    std::fclose(f);
  }
  EXPECT_THROW(ReadPng(path), Error);
}

}  // namespace
}  // namespace cablefilm
