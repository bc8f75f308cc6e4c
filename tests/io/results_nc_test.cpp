// The results.nc writer (io/netcdf_results): its compression and chunking, read back with the
// netCDF C API.
#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/netcdf_support.h"
#include "io/results_nc.h"
#include "run/run.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"
#include "nc_file.h"
#include "../core/text_support.h"

namespace cablefilm {
namespace {

namespace fs = std::filesystem;
using cablefilm_test::NcFile;

class NetcdfResultsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cablefilm_results_nc_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Case P63 cut to `duration` seconds.
  std::string ShortP63(const std::string& duration) {
    using cablefilm_test::ReadText;
    using cablefilm_test::Replace;
    const std::string text = ReadText(fs::path(CABLEFILM_SOURCE_DIR) / "scenes/polachek1963.toml");
    const fs::path p = dir_ / "p63_short.toml";
    std::ofstream(p, std::ios::binary) << Replace(text, "duration = 60.0", "duration = " + duration);
    return p.string();
  }
  fs::path dir_;
};

// The variables over time are deflated (level 1, shuffle) when the rows a complete run writes
// would make more than kDeflateAboveBytes of them, stored as they are below it; but along the
// cable only z of a scene in the plane (zeros) is, x, y and tension never (deflating them cost
// ten times the disk's time). The values read back are the same either way, and each chunk is
// written as it comes (not kept for the close: the file grows while it is open).
TEST_F(NetcdfResultsTest, DeflatedOnlyWhenLarge) {
  const SceneDef scene = LoadScene(ShortP63("1.0"));
  const cablefilm::Run run = PrepareRun(scene, BuildModel(scene), "elastic", nullptr);
  const LineModel& line = run.model.lines.front();
  const int stations = line.stations(), links = line.line.links;
  const double row_bytes = 8.0 * (3 * stations + links + 7);
  const long small_rows = 200, large_rows = static_cast<long>(kDeflateAboveBytes / row_bytes) + 1;
  auto info_of = [](long rows, bool planar = true) {
    NetcdfResultsInfo info;
    info.model = "elastic";
    info.initial_state = "equilibrium";
    info.rows = rows;
    info.planar = planar;
    return info;
  };
  EXPECT_FALSE(DeflateResults(info_of(large_rows - 1), row_bytes));
  EXPECT_TRUE(DeflateResults(info_of(large_rows), row_bytes));
  EXPECT_TRUE(DeflateResults(info_of(0), row_bytes));  // rows not known
  std::vector<std::vector<double>> values;
  // Small; large in the plane; large out of it (the flag told otherwise: the same content).
  struct Case {
    const char* name;
    long rows;
    bool planar;
  };
  for (const Case& c : {Case{"small", small_rows, true}, Case{"large", large_rows, true},
                        Case{"large_3d", large_rows, false}}) {
    const long rows = c.rows;
    State state = run.initial.lines.front().state;
    Eigen::VectorXd tension = run.initial.lines.front().tension();
    const fs::path path = dir_ / (std::string(c.name) + ".nc");
    std::unique_ptr<LineResultsNc> nc = OpenLineResultsNc(path.string(), info_of(rows, c.planar),
                                                          line, state, tension);
    std::uintmax_t open_size = 0;
    for (int r = 0; r < small_rows; ++r) {
      state.t = 0.1 * r;
      state.x(1, stations / 2) += 1e-3 * r;
      tension[r % links] += r;
      nc->Append(state, tension);
      if (r == small_rows - 1 && rows == small_rows) {
        // 3 chunks of 64 rows handed to the writer's thread: written before the close (more
        // than 2 chunks of x's 64 x 61 doubles in the file), not held in a cache until then.
        const std::uintmax_t two_chunks = 2 * 64 * 8 * static_cast<std::uintmax_t>(stations);
        for (int wait = 0; wait < 300 && open_size <= two_chunks; ++wait) {
          std::error_code ec;
          for (const auto& e : fs::directory_iterator(dir_))
            if (e.path().filename().string().rfind(path.filename().string() + ".tmp", 0) == 0)
              open_size = fs::file_size(e.path(), ec);
          if (open_size <= two_chunks) ::usleep(10000);
        }
        EXPECT_GT(open_size, two_chunks);
      }
    }
    nc->Commit();
    const NcFile f(path);
    // Along the cable (x, y, z, tension) only z in the plane; over time alone, every one.
    const bool large = rows == large_rows;
    const std::pair<const char*, bool> expected[] = {
        {"x", false}, {"y", false}, {"z", large && c.planar}, {"tension", false},
        {"time", large}, {"x_end", large}};
    for (const auto& [var, deflated] : expected) {
      int shuffle = -1, deflate = -1, level = -1;
      ASSERT_EQ(nc_inq_var_deflate(f.id(), f.Var(var), &shuffle, &deflate, &level), NC_NOERR);
      EXPECT_EQ(deflate, deflated ? 1 : 0) << var << " " << c.name;
      EXPECT_EQ(shuffle, deflated ? 1 : 0) << var << " " << c.name;
      if (deflated) {
        EXPECT_EQ(level, 1) << var;
      }
    }
    EXPECT_EQ(f.Dim("time"), static_cast<size_t>(small_rows));
    values.push_back(f.Values("y"));
    values.push_back(f.Values("tension"));
  }
  for (size_t k = 2; k < values.size(); ++k) EXPECT_EQ(values[k % 2], values[k]);
}

}  // namespace
}  // namespace cablefilm
