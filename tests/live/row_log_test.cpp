// The live time series' temporary file: bounded, the whole session kept ever more coarsely.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "live/row_log.h"

namespace cablefilm {
namespace {

std::vector<long> ReadRows(RowLog& log, std::string* header) {
  std::string text;
  log.Read(log.Flush(), [&](const char* data, std::size_t size) {
    text.append(data, size);
    return true;
  });
  std::istringstream in(text);
  std::getline(in, *header);
  std::vector<long> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(std::stol(line));
  return rows;
}

// 100 000 frames of rows "i\n" (1 to 6 bytes) into 4 kB: the file never exceeds its bound by
// more than the row that crossed it, it holds frame 0 and every stride-th frame after it in
// order, and the last kept frame is within a stride of the last frame.
TEST(RowLog, StaysWithinItsBoundKeepingTheWholeSessionCoarser) {
  constexpr long kBound = 4096, kFrames = 100000;
  RowLog log("t\n", kBound);
  for (long i = 0; i < kFrames; ++i) {
    log.Append([i](std::FILE* f) { std::fprintf(f, "%ld\n", i); });
    ASSERT_LE(log.Flush(), kBound + 7) << "frame " << i;
  }
  std::string header;
  const std::vector<long> rows = ReadRows(log, &header);
  EXPECT_EQ(header, "t");
  ASSERT_EQ(static_cast<long>(rows.size()), log.rows());
  const long stride = log.stride();
  EXPECT_GT(stride, 1);
  for (std::size_t k = 0; k < rows.size(); ++k) ASSERT_EQ(rows[k], static_cast<long>(k) * stride);
  EXPECT_GT(rows.back(), kFrames - 1 - stride);
  // Half the bound at least is rows: the thinning keeps the session's resolution as fine as
  // the bound allows (each thinning halves it once the file reaches the bound).
  EXPECT_GT(log.Flush(), kBound / 2);
  std::printf("[ row log ] %ld frames in %ld bytes: %ld rows, every %ld-th frame\n", kFrames,
              log.Flush(), log.rows(), stride);
}

TEST(RowLog, ARestartStartsAtFullResolution) {
  RowLog log("t\n", 256);
  for (long i = 0; i < 1000; ++i) log.Append([i](std::FILE* f) { std::fprintf(f, "%ld\n", i); });
  EXPECT_GT(log.stride(), 1);
  log.Clear();
  for (long i = 0; i < 5; ++i) log.Append([i](std::FILE* f) { std::fprintf(f, "%ld\n", i); });
  std::string header;
  EXPECT_EQ(ReadRows(log, &header), (std::vector<long>{0, 1, 2, 3, 4}));
  EXPECT_EQ(log.stride(), 1);
}

}  // namespace
}  // namespace cablefilm
