#pragma once
// JPEG of a picture that changes in places (the live view): only the tiles that changed since
// the last picture are encoded again. The JPEG has a restart marker after every tile (a run of
// up to 8 MCUs of 16x16 px, 128x16 px at 1280 or 1920 wide): a restart resets the DC
// predictors, so each tile's entropy-coded bytes depend on its own pixels only and can be kept
// from one picture to the next. The tiles that changed are gathered side by side into a small
// picture, encoded with the same tables and restart interval (one libjpeg call), and their bytes
// put in place: the file is byte for byte the one the whole picture would give (4:2:0,
// baseline, standard Huffman tables, the fast DCT). A width that is not a multiple of 16
// (no whole MCUs at the right edge) is encoded whole every time.
#include <cstdint>
#include <string>
#include <vector>

#include "encode/image.h"

namespace cablefilm {

class TiledJpegEncoder {
 public:
  explicit TiledJpegEncoder(int quality = 85);  // 1..100; throws Error
  TiledJpegEncoder(const TiledJpegEncoder&) = delete;
  TiledJpegEncoder& operator=(const TiledJpegEncoder&) = delete;

  // Appends the JPEG file of `image` (RGBA, the alpha ignored) to `out`. With `changed`, the
  // picture is the last one encoded but within those rectangles (the renderer redrew only
  // them): only the tiles they reach are compared.
  void Encode(const Image& image, std::string* out, const std::vector<ImageRect>* changed = nullptr);
  // The share of the picture's tiles the last Encode encoded (1: the whole picture).
  double reencoded() const { return reencoded_; }

 private:
  // Compresses w x h RGBA pixels (rows `stride` bytes apart) into compressed_.
  void Compress(const std::uint8_t* rgba, int width, int height, std::size_t stride);
  // Splits compressed_'s scan at its restart markers: the tiles in `slots` in order get the
  // segments (a slot of -1 is padding, its segment dropped). Keeps the header if `header`.
  void Split(const std::vector<int>& slots, bool header);
  void Reset(const Image& image);  // a new size: every tile encoded again

  int quality_;
  int width_ = 0, height_ = 0;
  int tile_w_ = 0, columns_ = 0, rows_ = 0;  // tiles of tile_w_ x 16 px (the last row less)
  bool tiled_ = false;
  bool kept_ = false;  // previous_, header_ and segments_ are the last picture's
  double reencoded_ = 1;
  Image previous_;                        // the last picture encoded
  std::string header_;                    // SOI to the scan's start
  std::vector<std::string> segments_;     // each tile's entropy-coded bytes
  std::vector<unsigned char> compressed_; // libjpeg's output
  std::vector<std::uint8_t> patch_;       // the changed tiles side by side
  std::vector<int> dirty_, slots_;        // changed tiles; tile of each patch slot
  std::vector<std::uint8_t> reached_;     // per tile: within a changed rectangle
};

}  // namespace cablefilm
