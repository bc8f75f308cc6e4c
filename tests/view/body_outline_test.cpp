// A body's outline through its points (view/body_outline.h): the points in turn about their
// centre and closed, whatever order the scene lists them in.
#include <gtest/gtest.h>

#include <cmath>

#include "view/body_outline.h"

namespace cablefilm {
namespace {

TEST(BodyOutline, GoesRoundItsPointsAndCloses) {
  // A square's corners listed across its diagonals: the outline goes round, not across.
  const std::vector<Vec2f> outline = BodyOutline(std::vector<Vec2f>{{1, 1}, {-1, -1}, {1, -1}, {-1, 1}});
  ASSERT_EQ(outline.size(), 5u);
  EXPECT_EQ(outline.front().x, outline.back().x);
  EXPECT_EQ(outline.front().y, outline.back().y);
  double perimeter = 0;
  for (std::size_t i = 1; i < outline.size(); ++i)
    perimeter += std::hypot(outline[i].x - outline[i - 1].x, outline[i].y - outline[i - 1].y);
  EXPECT_NEAR(perimeter, 8.0, 1e-6);  // round the 2 x 2 square; across would be longer
  EXPECT_EQ(BodyOutline(std::vector<Vec2f>{{1, 1}, {2, 3}}).size(), 2u);  // two points: a segment
  EXPECT_TRUE(BodyOutline(std::vector<Vec2f>{{1, 1}}).empty());
}

TEST(BodyOutline, InSpaceTurnsAboutTheVertical) {
  // Three fairleads 120 degrees apart at one depth, listed out of turn.
  std::vector<Vec3f> at;
  for (int i : {0, 2, 1})
    at.push_back({static_cast<float>(20 * std::cos(2 * M_PI * i / 3)), -10.0f,
                  static_cast<float>(20 * std::sin(2 * M_PI * i / 3))});
  const std::vector<Vec3f> outline = BodyOutline(at);
  ASSERT_EQ(outline.size(), 4u);
  double perimeter = 0;
  for (std::size_t i = 1; i < outline.size(); ++i)
    perimeter += std::hypot(outline[i].x - outline[i - 1].x, outline[i].z - outline[i - 1].z);
  EXPECT_NEAR(perimeter, 3 * 20 * std::sqrt(3.0), 1e-3);  // the triangle's three sides
  for (const Vec3f& q : outline) EXPECT_EQ(q.y, -10.0f);
}

}  // namespace
}  // namespace cablefilm
