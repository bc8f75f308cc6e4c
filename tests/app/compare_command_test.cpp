// `cablefilm compare`: the elastic and inextensible runs of a scene's lines. On case P63 (one
// line), both time series written, whole and finite. On a system (compare_system.toml: a leg
// of two lines joined at a free clump weight, and a lone leg), the lone line runs inextensible
// (its links keep their length), the joined ones stay elastic, said, and give the same bytes in
// both runs: islands step on their own, so the lone line's model cannot change the others.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "scene/scene_loader.h"
#include "../core/text_support.h"

#ifndef CABLEFILM_TEST_RENDER
#define CABLEFILM_TEST_RENDER 0
#endif

namespace cablefilm {
namespace {

namespace fs = std::filesystem;
using cablefilm_test::ReadText;

// The numbers of a CSV file's rows after its header; every field must be a finite number.
std::vector<std::vector<double>> ReadRows(const fs::path& path, bool* all_finite) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(ReadText(path));
  std::string line;
  *all_finite = true;
  if (!std::getline(in, line)) return rows;  // the header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      if (end == field.c_str() || !std::isfinite(v)) *all_finite = false;
      row.push_back(v);
    }
    rows.push_back(row);
  }
  return rows;
}

fs::path FreshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("cablefilm_compare_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(CompareCommand, OneLineWritesBothSeries) {
  const std::string p63 = std::string(CABLEFILM_SOURCE_DIR) + "/scenes/polachek1963.toml";
  const fs::path dir = FreshDir("p63");
  RunOptions o;
  o.out_dir = dir.string();
  o.film = 0;
  ASSERT_EQ(CompareCommand(p63, o), 0);
  const SceneDef scene = LoadScene(p63);
  const std::size_t expected =
      static_cast<std::size_t>(std::floor(scene.simulation.duration / scene.output.interval + 1e-9)) + 1;
  bool finite_el = false, finite_in = false;
  EXPECT_EQ(ReadRows(dir / "timeseries.csv", &finite_el).size(), expected);
  EXPECT_EQ(ReadRows(dir / "timeseries_inextensible.csv", &finite_in).size(), expected);
  EXPECT_TRUE(finite_el);
  EXPECT_TRUE(finite_in);
  // The figure needs the renderer (CABLEFILM_RENDER); without it nothing pretends to write it.
  EXPECT_EQ(fs::exists(dir / "max_tension.png"), CABLEFILM_TEST_RENDER != 0);
  fs::remove_all(dir);
}

TEST(CompareCommand, OnASystemTheLoneLineRunsInextensibleAndJoinedLinesStayElastic) {
  const std::string scene = std::string(CABLEFILM_SOURCE_DIR) + "/tests/app/compare_system.toml";
  const fs::path dir = FreshDir("system");
  RunOptions o;
  o.out_dir = dir.string();
  o.film = 0;
  testing::internal::CaptureStdout();
  const int status = CompareCommand(scene, o);
  std::fflush(stdout);
  const std::string said = testing::internal::GetCapturedStdout();
  ASSERT_EQ(status, 0) << said;
  for (const char* joined : {"lower", "upper"}) {
    const std::string name = std::string("\"") + joined + "\"";
    EXPECT_NE(said.find("line " + name + " is joined to other lines or to a free body"),
              std::string::npos) << said;
    EXPECT_NE(said.find("peak tension of line " + name + ": elastic"), std::string::npos);
    // Its island's steps do not depend on the other island's model: the same bytes.
    const fs::path folder = dir / "lines" / joined;
    EXPECT_EQ(ReadText(folder / "timeseries_inextensible.csv"), ReadText(folder / "timeseries.csv"))
        << joined;
    EXPECT_EQ(ReadText(folder / "equilibrium_inextensible.csv"), ReadText(folder / "equilibrium.csv"))
        << joined;
  }
  EXPECT_NE(said.find("peak tension of line \"alone\": elastic"), std::string::npos);
  EXPECT_NE(said.find("ratio inextensible/elastic"), std::string::npos);

  // The lone line (280 m in 40 links of 7 m): inextensible, each link of the equilibrium is
  // 7 m to the solver's constraint tolerance (1e-9 relative is far above it and far below the
  // elastic stretch T/EA ~ 1e-5 of its tension ~4e3 N over EA = 4e8 N, which the elastic
  // equilibrium must show).
  bool finite = false;
  const auto rigid = ReadRows(dir / "lines/alone/equilibrium_inextensible.csv", &finite);
  const auto elastic = ReadRows(dir / "lines/alone/equilibrium.csv", &finite);
  ASSERT_EQ(rigid.size(), 41u);
  ASSERT_EQ(elastic.size(), 41u);
  auto link = [](const std::vector<std::vector<double>>& rows, std::size_t j) {  // x, y, z: 2..4
    return std::hypot(rows[j + 1][2] - rows[j][2], rows[j + 1][3] - rows[j][3],
                      rows[j + 1][4] - rows[j][4]);
  };
  for (std::size_t j = 0; j + 1 < rigid.size(); ++j) {
    EXPECT_NEAR(link(rigid, j), 7.0, 7e-9) << j;
    const double tension = elastic[j][5], ea = 5e10 * 0.008;  // link j+1/2's, EA [N]
    EXPECT_NEAR(link(elastic, j), 7.0 * (1 + tension / ea), 1e-3 * 7.0 * tension / ea) << j;
  }
  const auto series = ReadRows(dir / "lines/alone/timeseries_inextensible.csv", &finite);
  EXPECT_EQ(series.size(), 9u);  // 4 s every 0.5 s
  EXPECT_TRUE(finite);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cablefilm
