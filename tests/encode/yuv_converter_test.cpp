// The film's colour conversion by tiles (encode/yuv_converter.h) against libswscale's
// conversion of the whole picture, byte for byte: the truth is the same library run over the
// whole frame, as the encoder did before the tiles.
#include "encode/yuv_converter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/error.h"

namespace cablefilm {
namespace {

// The three planes with rows padded to 64 bytes, as libavutil allocates a frame's
// (av_frame_get_buffer): swscale's vector code may write past a row's last pixel into the
// padding (a picture whose width is no multiple of 16). Compared on their pixels alone.
struct Planes {
  int width, height, stride[3];
  std::vector<std::uint8_t> plane[3];
  Planes(int w, int h) : width(w), height(h) {
    for (int k = 0; k < 3; ++k) {
      stride[k] = ((k ? w / 2 : w) + 63) / 64 * 64;
      plane[k].assign(std::size_t(stride[k]) * (k ? h / 2 : h), 0);
    }
  }
  void Convert(YuvConverter* c, const Image& im, const std::vector<ImageRect>* changed) {
    std::uint8_t* const planes[3] = {plane[0].data(), plane[1].data(), plane[2].data()};
    c->Convert(im, planes, stride, changed);
  }
  bool operator==(const Planes& o) const {
    for (int k = 0; k < 3; ++k) {
      const int w = k ? width / 2 : width, h = k ? height / 2 : height;
      for (int y = 0; y < h; ++y)
        if (!std::equal(plane[k].begin() + std::size_t(y) * stride[k],
                        plane[k].begin() + std::size_t(y) * stride[k] + w,
                        o.plane[k].begin() + std::size_t(y) * o.stride[k]))
          return false;
    }
    return true;
  }
};

// Noise everywhere: every pixel, horizontal pair and row pair differs from its neighbours, so
// a conversion that mixed pixels across a tile's edge (or misplaced a tile) would show.
Image Noise(int w, int h, std::mt19937* rng) {
  Image im(w, h);
  std::uniform_int_distribution<int> byte(0, 255);
  for (std::uint8_t& b : im.rgba) b = static_cast<std::uint8_t>(byte(*rng));
  return im;
}

// Repaints the rectangle with fresh noise.
void Repaint(Image* im, const ImageRect& r, std::mt19937* rng) {
  std::uniform_int_distribution<int> byte(0, 255);
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      for (int k = 0; k < 4; ++k) im->row(y)[4 * x + k] = static_cast<std::uint8_t>(byte(*rng));
}

// Sizes whose edges fall inside a tile (odd multiples of 2 px), and the film's 1080p.
class YuvTiles : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(YuvTiles, ChangedTilesGiveTheWholePicturesBytes) {
  const int w = GetParam().first, h = GetParam().second;
  std::mt19937 rng(7);
  Image im = Noise(w, h, &rng);
  YuvConverter tiles(w, h), whole(w, h);
  Planes kept(w, h);
  kept.Convert(&tiles, im, nullptr);
  EXPECT_EQ(tiles.converted(), 1.0);
  std::uniform_int_distribution<int> xs(0, w - 1), ys(0, h - 1), sizes(1, 40);
  for (int frame = 0; frame < 12; ++frame) {
    // A few small rectangles, the picture's edges among them (odd corners, inside tiles).
    std::vector<ImageRect> changed;
    for (int k = 0; k < 3; ++k) {
      ImageRect r;
      r.x0 = xs(rng);
      r.y0 = ys(rng);
      r.x1 = std::min(w, r.x0 + sizes(rng));
      r.y1 = std::min(h, r.y0 + sizes(rng));
      changed.push_back(r);
    }
    changed.push_back({w - 3, h - 5, w, h});
    for (const ImageRect& r : changed) Repaint(&im, r, &rng);
    kept.Convert(&tiles, im, &changed);
    EXPECT_GT(tiles.converted(), 0.0);
    EXPECT_LT(tiles.converted(), 1.0) << "the tiles were not used";
    Planes truth(w, h);
    truth.Convert(&whole, im, nullptr);
    ASSERT_TRUE(kept == truth) << "frame " << frame << " at " << w << "x" << h;
  }
  // Nothing changed: nothing converted, the planes as they were.
  const std::vector<ImageRect> none;
  kept.Convert(&tiles, im, &none);
  EXPECT_EQ(tiles.converted(), 0.0);
  Planes truth(w, h);
  truth.Convert(&whole, im, nullptr);
  EXPECT_TRUE(kept == truth);
}

INSTANTIATE_TEST_SUITE_P(Sizes, YuvTiles,
                         ::testing::Values(std::make_pair(1920, 1080), std::make_pair(326, 190),
                                           std::make_pair(642, 98)));

TEST(YuvConverter, RefusesOddSizesAndOtherPictures) {
  EXPECT_THROW(YuvConverter(15, 16), Error);
  YuvConverter c(64, 32);
  Image other(32, 32);
  std::vector<std::uint8_t> y(64 * 32), u(32 * 16), v(32 * 16);
  std::uint8_t* const planes[3] = {y.data(), u.data(), v.data()};
  const int linesize[3] = {64, 32, 32};
  EXPECT_THROW(c.Convert(other, planes, linesize), Error);
}

}  // namespace
}  // namespace cablefilm
