#include "view/damage.h"

#include <gtest/gtest.h>

namespace cablefilm {
namespace {

DrawnItem Item(std::uint64_t hash, int x0, int y0, int x1, int y1) { return {hash, x0, y0, x1, y1}; }

long Area(const std::vector<ImageRect>& rects) {
  long a = 0;
  for (const ImageRect& r : rects) a += static_cast<long>(r.x1 - r.x0) * (r.y1 - r.y0);
  return a;
}

// A 320x200 frame in 32 px tiles (10 x 7, the last row 8 px high).
TEST(Damage, NothingChangedNothingToDraw) {
  Damage d(320, 200);
  const std::vector<DrawnItem> items = {Item(1, 0, 0, 320, 200), Item(2, 10, 10, 50, 20)};
  std::vector<ImageRect> rects = {{0, 0, 1, 1}};
  ASSERT_TRUE(d.Compare(items, items, &rects));
  EXPECT_TRUE(rects.empty());
}

TEST(Damage, AMovedItemMarksWhereItWasAndWhereItIs) {
  Damage d(320, 200);
  const std::vector<DrawnItem> before = {Item(1, 0, 0, 320, 200), Item(2, 5, 5, 20, 20)};
  const std::vector<DrawnItem> after = {Item(1, 0, 0, 320, 200), Item(3, 100, 70, 120, 90)};
  std::vector<ImageRect> rects;
  ASSERT_TRUE(d.Compare(before, after, &rects));
  ASSERT_EQ(rects.size(), 2u);  // tile (0, 0) and tiles (3..., 2) of the new place
  EXPECT_EQ(Area(rects), 32 * 32 + 32 * 32);
  EXPECT_EQ(rects[0].x0, 0);
  EXPECT_EQ(rects[0].y1, 32);
  EXPECT_EQ(rects[1].x0, 96);
  EXPECT_EQ(rects[1].y0, 64);
  EXPECT_EQ(rects[1].x1, 128);
  EXPECT_EQ(rects[1].y1, 96);
}

TEST(Damage, TilesStackIntoOneRectangleAndOneGapIsBridged) {
  Damage d(320, 200);
  // Tiles 0 and 2 of rows 0 to 6 (x 0..95, the gap at tile 1 bridged), down to the frame's
  // bottom edge (200, not 224).
  const std::vector<DrawnItem> before;
  const std::vector<DrawnItem> after = {Item(7, 0, 0, 10, 200), Item(8, 70, 0, 90, 200)};
  std::vector<ImageRect> rects;
  ASSERT_TRUE(d.Compare(before, after, &rects));
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_EQ(rects[0].x0, 0);
  EXPECT_EQ(rects[0].x1, 96);
  EXPECT_EQ(rects[0].y0, 0);
  EXPECT_EQ(rects[0].y1, 200);
}

TEST(Damage, CommonItemsInAnotherOrderCannotBeCompared) {
  Damage d(320, 200);
  const std::vector<DrawnItem> before = {Item(1, 0, 0, 50, 50), Item(2, 20, 20, 70, 70)};
  const std::vector<DrawnItem> after = {Item(2, 20, 20, 70, 70), Item(1, 0, 0, 50, 50)};
  std::vector<ImageRect> rects;
  EXPECT_FALSE(d.Compare(before, after, &rects));
}

TEST(Damage, ItemsOffTheFrameAreClipped) {
  Damage d(320, 200);
  const std::vector<DrawnItem> before;
  const std::vector<DrawnItem> after = {Item(5, -1000000, -1000000, 1000000, 1000000),
                                        Item(6, 400, 300, 500, 400)};
  std::vector<ImageRect> rects;
  ASSERT_TRUE(d.Compare(before, after, &rects));
  EXPECT_EQ(Area(rects), 320 * 200);
}

}  // namespace
}  // namespace cablefilm
