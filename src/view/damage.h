#pragma once
// What changed between two frames drawn into the same framebuffer, as rectangles to redraw.
// Each frame is a list of drawn items (a shape, a text) in drawing order, each with a hash of
// what it draws (its vertices) and its pixel bounds. Items of one frame that the other lacks
// mark the tiles under their bounds; the rest of the picture is drawn by the same items in the
// same order, so it is the same pixels and need not be drawn again. The live view's frames
// change in a few places (the cable, the newest samples, the clock), so redrawing only those
// saves most of the software rasteriser's work.
#include <cstdint>
#include <vector>

#include "encode/image.h"

namespace cablefilm {

struct DrawnItem {
  std::uint64_t hash = 0;      // of what it draws
  int x0 = 0, y0 = 0, x1 = 0;  // pixel bounds [x0, x1) x [y0, y1), y down
  int y1 = 0;
};

// A 64-bit hash of bytes (a drawn item's vertices).
std::uint64_t HashBytes(const void* data, std::size_t size, std::uint64_t h = 14695981039346656037ull);

class Damage {
 public:
  // A frame of `width` x `height` pixels cut into square tiles of `tile` pixels.
  Damage(int width, int height, int tile = 32);

  // The rectangles (whole tiles, none overlapping) where `current` differs from `previous`;
  // false when the two cannot be compared item by item (the items common to both are not in
  // the same order): then the whole frame must be drawn. Keeps its storage: no allocation once
  // the frames' sizes settle.
  bool Compare(const std::vector<DrawnItem>& previous, const std::vector<DrawnItem>& current,
               std::vector<ImageRect>* rects);

 private:
  void Mark(const DrawnItem& item);

  int width_, height_, tile_, columns_, rows_;
  std::vector<std::uint8_t> dirty_;  // per tile, row by row
  std::vector<std::uint32_t> order_previous_, order_current_;  // indices sorted by hash
  std::vector<std::uint8_t> common_previous_, common_current_;
};

}  // namespace cablefilm
