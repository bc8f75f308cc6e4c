#pragma once
// RGBA -> yuv420p (BT.709, limited range) with libswscale for the film's encoder, of a whole
// picture or only of the tiles where it changed. A 2D film's frame differs from the one before
// where the lines, the newest samples and the clock moved (7 % of P63's pixels, 23 % with
// waves): the renderer redraws only there (renderer.h) and the planes keep the rest. swscale
// converts each pixel (and each horizontal pair and even-odd row pair, for chroma) on its own
// at the same size, so a tile of kTileWidth x kTileHeight px with even corners converted alone
// gives the bytes of the whole picture's conversion there (tests/encode/yuv_converter_test.cpp).
// The planes' rows must be padded as libavutil pads a frame's (av_frame_get_buffer): like a
// whole conversion, a tile at the right edge of a width that is no multiple of 16 may be
// written past its last pixel.
// Not thread-safe: one thread converts.
#include <cstdint>
#include <vector>

#include "encode/image.h"

struct SwsContext;

namespace cablefilm {

class YuvConverter {
 public:
  static constexpr int kTileWidth = 64, kTileHeight = 16;

  YuvConverter(int width, int height);  // even sizes; throws Error
  ~YuvConverter();
  YuvConverter(const YuvConverter&) = delete;
  YuvConverter& operator=(const YuvConverter&) = delete;

  // Converts `image` (the converter's size) into the three planes (Y full size, U and V half
  // in each direction; `linesize` bytes a row). With `changed`, the planes hold the conversion
  // of the image converted last, and `image` differs from that one only within those
  // rectangles: only the tiles they reach are converted (all of them when they are most of
  // the picture).
  void Convert(const Image& image, std::uint8_t* const planes[3], const int linesize[3],
               const std::vector<ImageRect>* changed = nullptr);
  // The share of the picture's tiles the last Convert converted (1: the whole picture).
  double converted() const { return converted_; }

 private:
  struct Sized {
    int width, height;
    SwsContext* context;
  };
  SwsContext* Context(int width, int height);  // made once per size (the whole, the tiles)
  void ConvertRect(const Image& image, int x, int y, int w, int h,
                   std::uint8_t* const planes[3], const int linesize[3]);

  int width_, height_, columns_, rows_;
  std::vector<Sized> contexts_;
  std::vector<char> marked_;  // a tile each, row by row: to convert
  double converted_ = 1;
};

}  // namespace cablefilm
