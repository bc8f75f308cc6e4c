#include "encode/yuv_converter.h"

extern "C" {
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <string>

#include "core/error.h"

namespace cablefilm {

YuvConverter::YuvConverter(int width, int height)
    : width_(width),
      height_(height),
      columns_((width + kTileWidth - 1) / kTileWidth),
      rows_((height + kTileHeight - 1) / kTileHeight) {
  if (width <= 0 || height <= 0 || width % 2 || height % 2)
    throw Error("yuv420p: width and height must be positive and even, got " +
                std::to_string(width) + "x" + std::to_string(height));
  marked_.assign(static_cast<std::size_t>(columns_) * rows_, 0);
  Context(width, height);  // the whole picture's, made now so that a failure shows at once
}

YuvConverter::~YuvConverter() {
  for (Sized& s : contexts_) sws_freeContext(s.context);
}

SwsContext* YuvConverter::Context(int width, int height) {
  for (const Sized& s : contexts_)
    if (s.width == width && s.height == height) return s.context;
  // The same size in and out, so the scaler only converts colours; BT.709, limited range.
  SwsContext* c = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height,
                                 AV_PIX_FMT_YUV420P, SWS_POINT, nullptr, nullptr, nullptr);
  if (!c) throw Error("cannot create the RGBA -> yuv420p converter");
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(c, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  contexts_.push_back({width, height, c});
  return c;
}

void YuvConverter::ConvertRect(const Image& image, int x, int y, int w, int h,
                               std::uint8_t* const planes[3], const int linesize[3]) {
  const std::uint8_t* src[1] = {image.rgba.data() + y * image.stride() + 4 * static_cast<std::size_t>(x)};
  const int src_stride[1] = {static_cast<int>(image.stride())};
  std::uint8_t* dst[3] = {planes[0] + static_cast<std::ptrdiff_t>(y) * linesize[0] + x,
                          planes[1] + static_cast<std::ptrdiff_t>(y / 2) * linesize[1] + x / 2,
                          planes[2] + static_cast<std::ptrdiff_t>(y / 2) * linesize[2] + x / 2};
  sws_scale(Context(w, h), src, src_stride, 0, h, dst, linesize);
}

void YuvConverter::Convert(const Image& image, std::uint8_t* const planes[3],
                           const int linesize[3], const std::vector<ImageRect>* changed) {
  if (image.width != width_ || image.height != height_)
    throw Error("yuv420p: the picture is " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + ", the converter's " + std::to_string(width_) +
                "x" + std::to_string(height_));
  long marked = 0;
  if (changed) {
    std::fill(marked_.begin(), marked_.end(), 0);
    for (const ImageRect& r : *changed) {
      const int x0 = std::clamp(r.x0, 0, width_), x1 = std::clamp(r.x1, 0, width_);
      const int y0 = std::clamp(r.y0, 0, height_), y1 = std::clamp(r.y1, 0, height_);
      if (x0 >= x1 || y0 >= y1) continue;
      for (int row = y0 / kTileHeight; row <= (y1 - 1) / kTileHeight; ++row)
        for (int col = x0 / kTileWidth; col <= (x1 - 1) / kTileWidth; ++col) {
          char& m = marked_[static_cast<std::size_t>(row) * columns_ + col];
          marked += !m;
          m = 1;
        }
    }
  }
  converted_ = changed ? static_cast<double>(marked) / marked_.size() : 1.0;
  // Most of the picture: one call over all of it, rather than hundreds of tiles.
  if (converted_ > 0.6) {
    converted_ = 1;
    ConvertRect(image, 0, 0, width_, height_, planes, linesize);
    return;
  }
  // Tile by tile: at most four sizes of tile (those at the right and bottom edges may be
  // smaller), so four contexts. Runs of tiles in one call were no faster (bench_film).
  for (int row = 0; row < rows_; ++row)
    for (int col = 0; col < columns_; ++col) {
      if (!marked_[static_cast<std::size_t>(row) * columns_ + col]) continue;
      const int x = col * kTileWidth, y = row * kTileHeight;
      ConvertRect(image, x, y, std::min(x + kTileWidth, width_) - x,
                  std::min(y + kTileHeight, height_) - y, planes, linesize);
    }
}

}  // namespace cablefilm
