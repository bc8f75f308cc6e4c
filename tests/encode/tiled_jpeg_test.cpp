#include "encode/tiled_jpeg.h"

#include <gtest/gtest.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>

#include <jpeglib.h>

namespace cablefilm {
namespace {

// A picture with detail everywhere (a gradient and a pattern), so that every tile has bytes of
// its own.
Image Picture(int w, int h) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = im.row(y) + 4 * x;
      p[0] = static_cast<std::uint8_t>(x * 255 / w);
      p[1] = static_cast<std::uint8_t>(y * 255 / h);
      p[2] = static_cast<std::uint8_t>(((x / 7) ^ (y / 5)) & 1 ? 200 : 40);
      p[3] = 255;
    }
  return im;
}

void Paint(Image* im, int x0, int y0, int x1, int y1, std::uint8_t v) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      std::uint8_t* p = im->row(y) + 4 * x;
      p[0] = v;
      p[1] = static_cast<std::uint8_t>(255 - v);
      p[2] = static_cast<std::uint8_t>(v / 2);
    }
}

std::string Encode(TiledJpegEncoder* e, const Image& im) {
  std::string out = "head";  // Encode appends
  e->Encode(im, &out);
  EXPECT_EQ(out.substr(0, 4), "head");
  return out.substr(4);
}

struct DecodeError {
  jpeg_error_mgr pub;
  std::jmp_buf jump;
};

// Decoded by libjpeg: RGB, or empty if the bytes are not a JPEG.
std::vector<std::uint8_t> Decode(const std::string& jpeg, int* w, int* h) {
  jpeg_decompress_struct cinfo;
  DecodeError err;
  cinfo.err = jpeg_std_error(&err.pub);
  err.pub.error_exit = [](j_common_ptr c) { std::longjmp(reinterpret_cast<DecodeError*>(c->err)->jump, 1); };
  std::vector<std::uint8_t> rgb;
  if (setjmp(err.jump)) {
    jpeg_destroy_decompress(&cinfo);
    return {};
  }
  jpeg_create_decompress(&cinfo);
  jpeg_mem_src(&cinfo, reinterpret_cast<const unsigned char*>(jpeg.data()), jpeg.size());
  jpeg_read_header(&cinfo, TRUE);
  cinfo.out_color_space = JCS_RGB;
  jpeg_start_decompress(&cinfo);
  *w = static_cast<int>(cinfo.output_width);
  *h = static_cast<int>(cinfo.output_height);
  rgb.resize(static_cast<std::size_t>(*w) * *h * 3);
  while (cinfo.output_scanline < cinfo.output_height) {
    JSAMPROW row = rgb.data() + static_cast<std::size_t>(cinfo.output_scanline) * *w * 3;
    jpeg_read_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_decompress(&cinfo);
  jpeg_destroy_decompress(&cinfo);
  return rgb;
}

// The same picture through libjpeg without restart markers (quality 85, 4:2:0, the fast DCT):
// the coefficients, hence the decoded pixels, must be the tiled file's.
std::string EncodePlain(const Image& im) {
  jpeg_compress_struct cinfo;
  jpeg_error_mgr err;
  cinfo.err = jpeg_std_error(&err);
  jpeg_create_compress(&cinfo);
  unsigned char* buf = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&cinfo, &buf, &size);
  cinfo.image_width = static_cast<JDIMENSION>(im.width);
  cinfo.image_height = static_cast<JDIMENSION>(im.height);
  cinfo.input_components = 4;
  cinfo.in_color_space = JCS_EXT_RGBA;
  jpeg_set_defaults(&cinfo);
  jpeg_set_quality(&cinfo, 85, TRUE);
  cinfo.dct_method = JDCT_IFAST;
  jpeg_start_compress(&cinfo, TRUE);
  while (cinfo.next_scanline < cinfo.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(im.row(static_cast<int>(cinfo.next_scanline)));
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  jpeg_destroy_compress(&cinfo);
  std::string out(reinterpret_cast<const char*>(buf), size);
  std::free(buf);
  return out;
}

// Mean absolute difference [1/255] between a decoded picture and its source.
double MeanError(const std::vector<std::uint8_t>& rgb, const Image& im) {
  double sum = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      for (int c = 0; c < 3; ++c)
        sum += std::abs(rgb[(static_cast<std::size_t>(y) * im.width + x) * 3 + c] - im.row(y)[4 * x + c]);
  return sum / (3.0 * im.width * im.height);
}

// Each picture of a changing sequence, encoded tile by tile after the first, is byte for byte
// the JPEG a fresh encoder makes of it whole; the share of tiles encoded again is counted.
// 1920x1080: tiles of 8 MCUs (128x16 px), 15 to a row, 68 rows (the last 8 px high): 1020.
TEST(TiledJpeg, ChangedTilesGiveTheWholePicturesBytes) {
  const int w = 1920, h = 1080;
  const double tiles = 15 * 68;
  TiledJpegEncoder tiled(85), hinted(85);  // `hinted` told where the picture changed
  Image im = Picture(w, h);
  struct Change {
    int x0, y0, x1, y1;
    double reencoded;  // tiles encoded again / all
  };
  const Change changes[] = {
      {0, 0, 0, 0, 1},                       // the first picture: whole
      {0, 0, 0, 0, 0},                       // the same again: no tile
      {700, 300, 701, 301, 1 / tiles},       // one pixel: its tile
      {120, 10, 140, 40, 6 / tiles},         // across tiles 0-1 and rows 0-2: 6 tiles
      {1800, 1074, 1920, 1080, 1 / tiles},   // the short bottom row's last tile
      {0, 1060, 1920, 1080, 30 / tiles},     // the two bottom rows, whole
      {400, 0, 420, 1080, 68 / tiles},       // a column of tiles top to bottom, both patches
      {0, 0, 1920, 900, 1},                  // most of it: whole again
  };
  std::uint8_t v = 0;
  for (const Change& c : changes) {
    Paint(&im, c.x0, c.y0, c.x1, c.y1, v += 37);
    const std::string got = Encode(&tiled, im);
    EXPECT_DOUBLE_EQ(tiled.reencoded(), c.reencoded) << c.x0 << "," << c.y0;
    TiledJpegEncoder fresh(85);
    EXPECT_TRUE(got == Encode(&fresh, im)) << "change at " << c.x0 << "," << c.y0;
    const std::vector<ImageRect> where = {{c.x0, c.y0, c.x1, c.y1}};
    std::string told;
    hinted.Encode(im, &told, &c == changes ? nullptr : &where);
    EXPECT_TRUE(told == got) << "change at " << c.x0 << "," << c.y0;
    EXPECT_DOUBLE_EQ(hinted.reencoded(), c.reencoded);
    int dw = 0, dh = 0, pw = 0, ph = 0;
    const std::vector<std::uint8_t> rgb = Decode(got, &dw, &dh);
    ASSERT_EQ(dw, w);
    ASSERT_EQ(dh, h);
    EXPECT_TRUE(rgb == Decode(EncodePlain(im), &pw, &ph));
    // Sharp 7x5 px stripes of blue 40/200 lose most of their colour to 4:2:0 (measured 14
    // levels of 255 on average, as without restart markers); a misplaced tile is more.
    EXPECT_LT(MeanError(rgb, im), 16.0);
  }
}

// 1280x720 (whole MCU rows to the bottom: one patch), 112 px wide (7 MCUs: tiles of 7), and a
// width of no whole MCUs (1000 px), encoded whole each time: each decodes to its picture.
TEST(TiledJpeg, OtherSizes) {
  struct Size {
    int w, h;
    double one_tile;  // the share of one tile, or 1 when not tiled
  };
  for (const Size s : {Size{1280, 720, 1 / 450.0}, Size{112, 64, 1 / 4.0}, Size{1000, 562, 1}}) {
    TiledJpegEncoder tiled(85);
    Image im = Picture(s.w, s.h);
    Encode(&tiled, im);
    EXPECT_EQ(tiled.reencoded(), 1);
    Paint(&im, 3, s.h - 2, 4, s.h - 1, 99);  // one pixel at the bottom left
    const std::string got = Encode(&tiled, im);
    EXPECT_DOUBLE_EQ(tiled.reencoded(), s.one_tile) << s.w;
    TiledJpegEncoder fresh(85);
    EXPECT_TRUE(got == Encode(&fresh, im)) << s.w;
    int dw = 0, dh = 0, pw = 0, ph = 0;
    const std::vector<std::uint8_t> rgb = Decode(got, &dw, &dh);
    ASSERT_EQ(dw, s.w);
    ASSERT_EQ(dh, s.h);
    EXPECT_TRUE(rgb == Decode(EncodePlain(im), &pw, &ph)) << s.w;
    EXPECT_LT(MeanError(rgb, im), 16.0) << s.w;
  }
}

TEST(TiledJpeg, BadQualityAndImageAreErrors) {
  EXPECT_ANY_THROW(TiledJpegEncoder(0));
  EXPECT_ANY_THROW(TiledJpegEncoder(101));
  TiledJpegEncoder e(85);
  Image bad(16, 16);
  bad.rgba.resize(10);
  std::string out;
  EXPECT_ANY_THROW(e.Encode(bad, &out));
}

}  // namespace
}  // namespace cablefilm
