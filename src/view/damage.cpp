#include "view/damage.h"

#include <algorithm>
#include <cstring>

namespace cablefilm {

std::uint64_t HashBytes(const void* data, std::size_t size, std::uint64_t h) {
  // Eight bytes a step (a vertex is 20 or 36 bytes): byte-wise FNV took 2 % of the live view's
  // CPU (perf).
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    std::uint64_t w;
    std::memcpy(&w, p + i, 8);
    h = (h ^ w) * 0x9E3779B97F4A7C15ull;
    h ^= h >> 29;
  }
  for (; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

Damage::Damage(int width, int height, int tile)
    : width_(width),
      height_(height),
      tile_(tile),
      columns_((width + tile - 1) / tile),
      rows_((height + tile - 1) / tile),
      dirty_(static_cast<std::size_t>(columns_) * rows_) {}

void Damage::Mark(const DrawnItem& item) {
  const int x0 = std::max(item.x0, 0), y0 = std::max(item.y0, 0);
  const int x1 = std::min(item.x1, width_), y1 = std::min(item.y1, height_);
  if (x1 <= x0 || y1 <= y0) return;  // off the frame
  for (int r = y0 / tile_; r <= (y1 - 1) / tile_; ++r)
    for (int c = x0 / tile_; c <= (x1 - 1) / tile_; ++c) dirty_[static_cast<std::size_t>(r) * columns_ + c] = 1;
}

bool Damage::Compare(const std::vector<DrawnItem>& previous, const std::vector<DrawnItem>& current,
                     std::vector<ImageRect>* rects) {
  rects->clear();
  std::fill(dirty_.begin(), dirty_.end(), 0);
  // Pair equal items of the two frames by sorting both by hash and merging.
  auto sort_by_hash = [](const std::vector<DrawnItem>& items, std::vector<std::uint32_t>* order) {
    order->resize(items.size());
    for (std::uint32_t i = 0; i < order->size(); ++i) (*order)[i] = i;
    std::sort(order->begin(), order->end(), [&](std::uint32_t a, std::uint32_t b) {
      return items[a].hash < items[b].hash || (items[a].hash == items[b].hash && a < b);
    });
  };
  sort_by_hash(previous, &order_previous_);
  sort_by_hash(current, &order_current_);
  common_previous_.assign(previous.size(), 0);
  common_current_.assign(current.size(), 0);
  for (std::size_t i = 0, k = 0; i < order_previous_.size() && k < order_current_.size();) {
    const std::uint64_t a = previous[order_previous_[i]].hash, b = current[order_current_[k]].hash;
    if (a < b) {
      ++i;
    } else if (b < a) {
      ++k;
    } else {
      common_previous_[order_previous_[i++]] = 1;
      common_current_[order_current_[k++]] = 1;
    }
  }
  // The common items must be drawn in the same order, else what they overlap could differ.
  std::size_t i = 0, k = 0;
  while (true) {
    while (i < previous.size() && !common_previous_[i]) Mark(previous[i++]);
    while (k < current.size() && !common_current_[k]) Mark(current[k++]);
    if (i == previous.size() || k == current.size()) break;
    if (previous[i++].hash != current[k++].hash) return false;
  }
  // Runs of dirty tiles along each row (a gap of one clean tile bridged: one more tile drawn
  // costs less than one more pass), stacked into one rectangle while the run repeats below.
  std::size_t open = 0;  // rects from here on end at the row above
  for (int r = 0; r < rows_; ++r) {
    const std::size_t before = rects->size();
    const std::uint8_t* row = dirty_.data() + static_cast<std::size_t>(r) * columns_;
    for (int c = 0; c < columns_;) {
      if (!row[c]) {
        ++c;
        continue;
      }
      int end = c + 1;
      while (end < columns_ && (row[end] || (end + 1 < columns_ && row[end + 1]))) ++end;
      const int x0 = c * tile_, x1 = std::min(end * tile_, width_);
      const int y0 = r * tile_, y1 = std::min((r + 1) * tile_, height_);
      bool stacked = false;
      for (std::size_t j = open; j < before && !stacked; ++j) {
        ImageRect& o = (*rects)[j];
        if (o.x0 == x0 && o.x1 == x1 && o.y1 == y0) {
          o.y1 = y1;
          stacked = true;
        }
      }
      if (!stacked) rects->push_back({x0, y0, x1, y1});
      c = end;
    }
    // Rects that did not grow into this row are closed: keep them before the open ones.
    std::size_t closed = open;
    for (std::size_t j = open; j < rects->size(); ++j)
      if ((*rects)[j].y1 != std::min((r + 1) * tile_, height_)) std::swap((*rects)[closed++], (*rects)[j]);
    open = closed;
  }
  return true;
}

}  // namespace cablefilm
