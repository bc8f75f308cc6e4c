// results.nc as the run command writes it, read back with the netCDF C API: its dimensions,
// units and attributes, and its values against what the run computed and against
// timeseries.csv and equilibrium.csv; the .partial file of a blown-up run; the names of compare
// and the removal of earlier results; the utilisation of a material's breaking load. (Its
// compression and chunking, the writer's own: tests/io/results_nc_test.cpp.)
#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "app/commands.h"
#include "io/output_ledger.h"
#include "io/results_nc.h"
#include "io/run_report_file.h"
#include "run/driver.h"
#include "run/initial_state.h"
#include "run/run.h"
#include "run/time_grid.h"
#include "core/stability.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"
#include "../run/drive_support.h"
#include "../run/scene_line.h"
#include "../io/nc_file.h"

namespace cablefilm {
namespace {

namespace fs = std::filesystem;
using cablefilm_test::NcFile;

std::string ReadText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test bug: \"" + from + "\" not found");
  return text.replace(at, from.size(), to);
}

// The cells of a CSV file, header row first.
std::vector<std::vector<std::string>> ReadCsv(const fs::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(ReadText(p));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream l(line);
    while (std::getline(l, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    rows.push_back(cells);
  }
  return rows;
}

// A number as the CSV files print it.
std::string Format(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}


class NetcdfResultsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cablefilm_netcdf_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Case P63 cut to `duration` seconds, without its film.
  std::string ShortP63(const std::string& duration) {
    const std::string text = ReadText(fs::path(CABLEFILM_SOURCE_DIR) / "scenes/polachek1963.toml");
    const fs::path p = dir_ / "p63_short.toml";
    std::ofstream(p, std::ios::binary)
        << Replace(Replace(text, "duration = 60.0", "duration = " + duration), "film = true",
                   "film = false");
    return p.string();
  }
  // No temporary file left in the output folder.
  void ExpectNoTemporaryFiles(const fs::path& out) {
    for (const auto& e : fs::directory_iterator(out))
      EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
  fs::path dir_;
};

TEST_F(NetcdfResultsTest, EveryLinkOverTimeAgreesWithTheRunAndTheCsv) {
  const std::string scene = ShortP63("5.0");
  RunOptions opt;
  opt.out_dir = (dir_ / "out").string();
  ASSERT_EQ(RunCommand(scene, opt), 0);
  const fs::path out = dir_ / "out";
  ASSERT_TRUE(fs::exists(out / "results.nc"));
  EXPECT_FALSE(fs::exists(out / "results.partial.nc"));
  ExpectNoTemporaryFiles(out);

  const auto csv = ReadCsv(out / "timeseries.csv");
  ASSERT_EQ(csv[0], (std::vector<std::string>{"t", "x_end", "y_end", "z_end", "tension_start",
                                              "tension_end", "tension_max", "link_max",
                                              "fx_start", "fy_start", "fz_start", "fx_end",
                                              "fy_end", "fz_end", "angle_start",
                                              "angle_end"}));
  const size_t rows = csv.size() - 1;
  ASSERT_EQ(rows, 151u);  // 5 s at a row per film frame, 30 frames/s, and t = 0

  NcFile nc(out / "results.nc");
  // Dimensions: time unlimited.
  EXPECT_EQ(nc.Dim("time"), rows);
  EXPECT_EQ(nc.Dim("station"), 61u);
  EXPECT_EQ(nc.Dim("link"), 60u);
  int unlimited = -1, time_dim = -1, format = 0;
  ASSERT_EQ(nc_inq_unlimdim(nc.id(), &unlimited), NC_NOERR);
  ASSERT_EQ(nc_inq_dimid(nc.id(), "time", &time_dim), NC_NOERR);
  EXPECT_EQ(unlimited, time_dim);
  ASSERT_EQ(nc_inq_format(nc.id(), &format), NC_NOERR);
  EXPECT_EQ(format, NC_FORMAT_NETCDF4);
  EXPECT_EQ(nc.Dims("x"), "time,station");
  EXPECT_EQ(nc.Dims("y"), "time,station");
  EXPECT_EQ(nc.Dims("z"), "time,station");
  EXPECT_EQ(nc.Dims("tension"), "time,link");
  EXPECT_EQ(nc.Dims("x_end"), "time");
  EXPECT_EQ(nc.Dims("z_start"), "time");
  EXPECT_EQ(nc.Dims("z_end"), "time");
  EXPECT_EQ(nc.Dims("z_equilibrium"), "station");
  EXPECT_EQ(nc.Dims("s"), "station");
  EXPECT_EQ(nc.Dims("s_link"), "link");
  EXPECT_EQ(nc.Dims("tension_equilibrium"), "link");

  // Units, and a long name on every variable.
  const std::pair<const char*, const char*> units[] = {
      {"time", "s"},          {"x", "m"},          {"y", "m"},          {"z", "m"},
      {"tension", "N"},       {"s", "m"},          {"s_link", "m"},
      {"x_start", "m"},       {"y_start", "m"},    {"z_start", "m"},
      {"x_end", "m"},         {"y_end", "m"},      {"z_end", "m"},
      {"x_equilibrium", "m"}, {"y_equilibrium", "m"}, {"z_equilibrium", "m"},
      {"tension_equilibrium", "N"}, {"station", "1"}, {"link", "1"},
      {"tension_start_mean", "N"}, {"tension_start_std", "N"}, {"tension_start_min", "N"},
      {"tension_start_max", "N"}, {"tension_start_upcrossings", "1"},
      {"tension_start_mpm", "N"}, {"tension_start_psd_m0", "N^2"},
      {"tension_end_mean", "N"}, {"tension_end_std", "N"}, {"tension_end_min", "N"},
      {"tension_end_max", "N"}, {"tension_end_upcrossings", "1"},
      {"tension_end_mpm", "N"}, {"tension_end_psd_m0", "N^2"}};
  for (const auto& [var, unit] : units) EXPECT_EQ(nc.Attr(var, "units"), unit) << var;
  int nvars = 0;
  ASSERT_EQ(nc_inq_nvars(nc.id(), &nvars), NC_NOERR);
  EXPECT_EQ(nvars, static_cast<int>(std::size(units)));
  for (int v = 0; v < nvars; ++v) {
    char name[NC_MAX_NAME + 1];
    ASSERT_EQ(nc_inq_varname(nc.id(), v, name), NC_NOERR);
    EXPECT_GT(nc.Attr(v, "long_name").size(), 4u) << name;
    EXPECT_EQ(nc.Attr(v, "long_name").find("(no "), std::string::npos) << name;
  }

  // Global attributes: CF, the scene and the program.
  EXPECT_EQ(nc.Attr(NC_GLOBAL, "Conventions"), "CF-1.8");
  EXPECT_EQ(nc.Attr(NC_GLOBAL, "title"), LoadScene(scene).title);
  EXPECT_EQ(nc.Attr(NC_GLOBAL, "scene"), ReadText(scene));
  EXPECT_EQ(nc.Attr(NC_GLOBAL, "scene_file"), scene);
  EXPECT_EQ(nc.Attr(NC_GLOBAL, "cablefilm_version").rfind(CABLEFILM_VERSION, 0), 0u)
      << nc.Attr(NC_GLOBAL, "cablefilm_version");
  EXPECT_EQ(nc.Attr(NC_GLOBAL, "source").rfind("cablefilm " CABLEFILM_VERSION, 0), 0u);
  EXPECT_EQ(nc.Attr(NC_GLOBAL, "model"), "elastic");
  EXPECT_EQ(nc.Attr(NC_GLOBAL, "initial_state"), "equilibrium");

  // Chunked by time (many rows of all stations a chunk); not deflated, the file being small
  // (DeflatedOnlyWhenLarge).
  for (const char* var : {"x", "y", "z", "tension"}) {
    int shuffle = -1, deflate = -1, level = -1, storage = -1;
    ASSERT_EQ(nc_inq_var_deflate(nc.id(), nc.Var(var), &shuffle, &deflate, &level), NC_NOERR);
    EXPECT_EQ(shuffle, 0) << var;
    EXPECT_EQ(deflate, 0) << var;
    size_t chunks[2] = {0, 0};
    ASSERT_EQ(nc_inq_var_chunking(nc.id(), nc.Var(var), &storage, chunks), NC_NOERR);
    EXPECT_EQ(storage, NC_CHUNKED) << var;
    EXPECT_GE(chunks[0], 16u) << var;
    EXPECT_EQ(chunks[1], std::string(var) == "tension" ? 60u : 61u) << var;
  }

  const std::vector<double> t = nc.Values("time"), x = nc.Values("x"), y = nc.Values("y"),
                            z = nc.Values("z"), tension = nc.Values("tension"),
                            x_end = nc.Values("x_end"), y_end = nc.Values("y_end"),
                            z_end = nc.Values("z_end"), x_start = nc.Values("x_start"),
                            y_start = nc.Values("y_start"), z_start = nc.Values("z_start");
  // Every row against timeseries.csv, as the CSV prints it: tension_max is the largest
  // tension of the row, link_max its link, tension_start and tension_end the first and the
  // last link; x_end, y_end, z_end the end's position, which is the last station's.
  for (size_t r = 0; r < rows; ++r) {
    const auto& c = csv[r + 1];
    ASSERT_EQ(c.size(), 16u);  // the end loads after link_max (checked in core_end_loads_test)
    const double* row = tension.data() + r * 60;
    const auto max_at = std::max_element(row, row + 60);
    EXPECT_EQ(Format("%.10g", t[r]), c[0]) << "row " << r;
    EXPECT_EQ(Format("%.12g", x_end[r]), c[1]) << "row " << r;
    EXPECT_EQ(Format("%.12g", y_end[r]), c[2]) << "row " << r;
    EXPECT_EQ(c[3], "0") << "row " << r;  // P63 is in the x-y plane
    EXPECT_EQ(Format("%.10g", row[0]), c[4]) << "row " << r;
    EXPECT_EQ(Format("%.10g", row[59]), c[5]) << "row " << r;
    EXPECT_EQ(Format("%.10g", *max_at), c[6]) << "row " << r;
    EXPECT_EQ(std::to_string(max_at - row), c[7]) << "row " << r;
    EXPECT_EQ(x_end[r], x[r * 61 + 60]);
    EXPECT_EQ(y_end[r], y[r * 61 + 60]);
    EXPECT_EQ(z_end[r], z[r * 61 + 60]);
    EXPECT_EQ(x_start[r], x[r * 61]);
    EXPECT_EQ(y_start[r], y[r * 61]);
    EXPECT_EQ(z_start[r], z[r * 61]);
    EXPECT_EQ(x_start[r], 0.0);  // the anchor
  }
  // A scene in the x-y plane stays in it: z is exactly 0 at every station of every row.
  EXPECT_EQ(std::count(z.begin(), z.end(), 0.0), static_cast<long>(z.size()));
  EXPECT_EQ(z.size(), rows * 61);

  // One time, bit for bit what the run computed (the same simulation in this process).
  const size_t at_row = 100;  // t = 3.333 s
  const SceneDef def = LoadScene(scene);
  const LineModel m = LineOf(def);
  const TimeGrid grid = ChooseLineGrid(m, def.simulation, def.output.interval);
  State state = InitialStateOf(def);
  auto integrator = testing::MakeStepper(m, grid);
  size_t row = 0;
  Eigen::VectorXd computed;
  Points where;
  testing::Simulate(m, *integrator, state, grid, [&](const State& s, const Eigen::VectorXd& T) {
    if (row++ != at_row) return true;
    computed = T;
    where = s.x;
    return false;
  });
  ASSERT_EQ(computed.size(), 60);
  EXPECT_EQ(tension[at_row * 60 + 18], computed[18]);  // the link below the weight
  for (int j = 0; j < 60; ++j) EXPECT_EQ(tension[at_row * 60 + j], computed[j]) << "link " << j;
  for (int j = 0; j < 61; ++j) {
    EXPECT_EQ(x[at_row * 61 + j], where(0, j)) << "station " << j;
    EXPECT_EQ(y[at_row * 61 + j], where(1, j)) << "station " << j;
    EXPECT_EQ(z[at_row * 61 + j], where(2, j)) << "station " << j;
  }

  // The arc lengths and the equilibrium against equilibrium.csv.
  const auto eq = ReadCsv(out / "equilibrium.csv");
  ASSERT_EQ(eq.size(), 62u);
  ASSERT_EQ(eq[0], (std::vector<std::string>{"j", "s", "x", "y", "z", "tension"}));
  const std::vector<double> s = nc.Values("s"), s_link = nc.Values("s_link"),
                            x_eq = nc.Values("x_equilibrium"), y_eq = nc.Values("y_equilibrium"),
                            z_eq = nc.Values("z_equilibrium"),
                            t_eq = nc.Values("tension_equilibrium"),
                            station = nc.Values("station"), link = nc.Values("link");
  for (int j = 0; j <= 60; ++j) {
    const auto& c = eq[static_cast<size_t>(j) + 1];
    EXPECT_EQ(station[static_cast<size_t>(j)], j);
    EXPECT_EQ(Format("%.10g", s[static_cast<size_t>(j)]), c[1]) << "station " << j;
    EXPECT_EQ(Format("%.12g", x_eq[static_cast<size_t>(j)]), c[2]) << "station " << j;
    EXPECT_EQ(Format("%.12g", y_eq[static_cast<size_t>(j)]), c[3]) << "station " << j;
    EXPECT_EQ(z_eq[static_cast<size_t>(j)], 0.0) << "station " << j;
    EXPECT_EQ(c[4], "0") << "station " << j;
    if (j == 60) break;
    EXPECT_EQ(link[static_cast<size_t>(j)], j);
    EXPECT_EQ(Format("%.10g", t_eq[static_cast<size_t>(j)]), c[5]) << "link " << j;
    EXPECT_DOUBLE_EQ(s_link[static_cast<size_t>(j)], 0.5 * (s[static_cast<size_t>(j)] +
                                                             s[static_cast<size_t>(j) + 1]));
  }
  // The first row is the initial state.
  for (int j = 0; j <= 60; ++j) EXPECT_EQ(x[static_cast<size_t>(j)], x_eq[static_cast<size_t>(j)]);
  EXPECT_DOUBLE_EQ(s_link[0], 45.72 / 30 / 2);
}

// Case P63 turned out of its plane (issue 19): a current of 0.5 m/s along +z (heading 90
// degrees), across the cable, and the fairlead swaying along z as well as on its circle. The z
// columns of timeseries.csv and equilibrium.csv and the z variables of results.nc agree as the
// CSV prints them; z_end is eq. (3)'s trochoid along z, worked out here from the scene's numbers;
// the anchor stays at z = 0; and the current pushes every other station towards +z.
TEST_F(NetcdfResultsTest, EndTensionStatisticsAgreeWithTheCsvInEveryFile) {
  // P63 for 20 s at its 1/30 s rows (601): the statistics of tension_start and tension_end
  // recomputed from timeseries.csv (10 significant digits) against run_report.toml,
  // results.nc and tension_spectrum.csv.
  const std::string scene = ShortP63("20.0");
  RunOptions opt;
  opt.out_dir = (dir_ / "out").string();
  ASSERT_EQ(RunCommand(scene, opt), 0);
  const fs::path out = dir_ / "out";
  const auto csv = ReadCsv(out / "timeseries.csv");
  RunSummary report;
  ASSERT_TRUE(ReadRunReport((out / "run_report.toml").string(), &report));
  NcFile nc(out / "results.nc");
  const auto spectrum = ReadCsv(out / "tension_spectrum.csv");
  ASSERT_EQ(spectrum[0],
            (std::vector<std::string>{"frequency", "tension_start_psd", "tension_end_psd"}));
  const std::size_t n = csv.size() - 1;
  ASSERT_EQ(n, 601u);
  const char* names[2] = {"tension_start", "tension_end"};
  for (int e = 0; e < 2; ++e) {
    const std::size_t column = 4 + static_cast<std::size_t>(e);
    ASSERT_EQ(csv[0][column], names[e]);
    std::vector<double> x;
    for (std::size_t r = 1; r <= n; ++r) x.push_back(std::stod(csv[r][column]));
    double mean = 0;
    for (double v : x) mean += v;
    mean /= static_cast<double>(n);
    double var = 0;
    for (double v : x) var += (v - mean) * (v - mean);
    var /= static_cast<double>(n);
    long up = 0;
    for (std::size_t r = 1; r < n; ++r) up += x[r - 1] < mean && x[r] >= mean;
    const TensionStatistics& s = report.ends[e];
    const std::string what = names[e];
    // The CSV's 10 digits: a relative 5e-10 each, and less on their mean.
    EXPECT_EQ(s.samples, static_cast<long>(n)) << what;
    EXPECT_NEAR(s.mean, mean, 1e-9 * mean) << what;
    EXPECT_NEAR(s.sigma, std::sqrt(var), 1e-6 * std::sqrt(var) + 1e-9 * mean) << what;
    EXPECT_EQ(Format("%.10g", s.max), Format("%.10g", *std::max_element(x.begin(), x.end())));
    EXPECT_EQ(Format("%.10g", s.min), Format("%.10g", *std::min_element(x.begin(), x.end())));
    EXPECT_EQ(s.upcrossings, up) << what;
    EXPECT_GT(up, 3) << what;  // P63's 6 s period over 20 s
    EXPECT_NEAR(s.mpm, mean + std::sqrt(var) * std::sqrt(2 * std::log(double(up))),
                1e-6 * mean) << what;
    // results.nc: the same numbers (the report has 10 digits).
    const std::string prefix = what + "_";
    EXPECT_NEAR(nc.Values((prefix + "mean").c_str())[0], s.mean, 1e-9 * s.mean);
    EXPECT_NEAR(nc.Values((prefix + "std").c_str())[0], s.sigma, 1e-9 * s.sigma);
    EXPECT_NEAR(nc.Values((prefix + "max").c_str())[0], s.max, 1e-9 * s.max);
    EXPECT_NEAR(nc.Values((prefix + "min").c_str())[0], s.min, 1e-9 * s.min);
    EXPECT_EQ(nc.Values((prefix + "upcrossings").c_str())[0], static_cast<double>(up));
    EXPECT_NEAR(nc.Values((prefix + "mpm").c_str())[0], s.mpm, 1e-9 * s.mpm);
    // The spectrum: 601 rows, segments of 64 (601 / 8 = 75), 33 frequencies to 15 Hz; its
    // integral the report's psd_m0 and, by Parseval, the Hann-weighted mean square about the
    // mean of the 17 half-overlapping segments, summed here in the time domain.
    ASSERT_EQ(spectrum.size(), 34u);
    const double df = std::stod(spectrum[2][0]) - std::stod(spectrum[1][0]);
    EXPECT_NEAR(df, 1 / (64 / 30.0), 1e-9);
    double m0 = 0;
    for (std::size_t k = 1; k < spectrum.size(); ++k) m0 += std::stod(spectrum[k][1 + e]) * df;
    EXPECT_NEAR(m0, s.psd_m0, 1e-8 * m0) << what;
    double weighted = 0;
    int segments = 0;
    for (std::size_t first = 0; first + 64 <= n; first += 32, ++segments) {
      double sum = 0, power = 0;
      for (int j = 0; j < 64; ++j) {
        const double w = 0.5 * (1 - std::cos(2 * M_PI * j / 64));
        sum += w * w * std::pow(x[first + j] - s.mean, 2);
        power += w * w;
      }
      weighted += sum / power;
    }
    EXPECT_EQ(segments, 17);
    EXPECT_NEAR(m0, weighted / segments, 1e-8 * m0) << what;
  }
  // The run's report of one line is its line's; a sweep's row would have the same cells.
  const std::vector<std::string> cells = SummaryCells(report);
  EXPECT_EQ(cells.size(), std::size(kSummaryColumns));
}

TEST_F(NetcdfResultsTest, ThreeDimensionalSceneHasZEverywhere) {
  const fs::path scene = dir_ / "p63_3d.toml";
  {
    std::string text = ReadText(ShortP63("3.0"));
    text = Replace(text, "current = 0.0 ", "current = 0.5\ncurrent_heading = 90.0 ");
    text = Replace(text, "y_amplitudes = [0.0, 1.8288]",
                   "y_amplitudes = [0.0, 1.8288]\nz_amplitudes = [0.0, 1.0]");
    std::ofstream(scene, std::ios::binary) << text;
  }
  RunOptions opt;
  opt.out_dir = (dir_ / "out").string();
  ASSERT_EQ(RunCommand(scene.string(), opt), 0);
  const fs::path out = dir_ / "out";
  const auto csv = ReadCsv(out / "timeseries.csv");
  const auto eq = ReadCsv(out / "equilibrium.csv");
  ASSERT_EQ(csv.size(), 92u);  // 3 s, 30 rows a second, and t = 0
  ASSERT_EQ(eq.size(), 62u);
  ASSERT_EQ(csv[0][3], "z_end");
  ASSERT_EQ(eq[0][4], "z");
  NcFile nc(out / "results.nc");
  const std::vector<double> t = nc.Values("time"), z = nc.Values("z"),
                            z_end = nc.Values("z_end"), z_start = nc.Values("z_start"),
                            z_eq = nc.Values("z_equilibrium");
  ASSERT_EQ(z.size(), 91u * 61);
  double largest_z = 0, largest_z_end = 0;
  for (size_t r = 0; r < 91; ++r) {
    // z = z0 + R(t) (e cos wt + f sin wt) with z0 = 0, [e, f] = [0, 1] m, w = 2 pi / 10 s,
    // R(t) = 1 - (1 + nu t) exp(-nu t), nu = 0.5 /s. The program evaluates the same formula in
    // its own arrangement: round-off of 1e-16 of a metre, 1e-12 m leaves room.
    const double nu = 0.5, R = 1 - (1 + nu * t[r]) * std::exp(-nu * t[r]);
    EXPECT_NEAR(z_end[r], R * std::sin(2 * M_PI * t[r] / 10.0), 1e-12) << "row " << r;
    EXPECT_EQ(z_end[r], z[r * 61 + 60]) << "row " << r;
    EXPECT_EQ(Format("%.12g", z_end[r]), csv[r + 1][3]) << "row " << r;
    EXPECT_EQ(z_start[r], 0.0) << "row " << r;  // the anchor
    EXPECT_EQ(z[r * 61], 0.0) << "row " << r;
    for (size_t j = 1; j < 60; ++j) {
      EXPECT_GT(z[r * 61 + j], 0.0) << "row " << r << " station " << j;
      largest_z = std::max(largest_z, z[r * 61 + j]);
    }
    largest_z_end = std::max(largest_z_end, std::abs(z_end[r]));
  }
  // Out of the plane by a measurable amount: the sway has R(3 s) sin(0.6 pi) = 0.42 m at 3 s,
  // and 0.5 m/s across 91 m of line bows it by metres.
  EXPECT_GT(largest_z_end, 0.4);
  EXPECT_GT(largest_z, 1.0);
  for (size_t j = 0; j <= 60; ++j) {
    EXPECT_EQ(Format("%.12g", z_eq[j]), eq[j + 1][4]) << "station " << j;
    EXPECT_EQ(z_eq[j], z[j]) << "station " << j;  // the first row is the initial state
  }
}

TEST_F(NetcdfResultsTest, BlownUpRunLeavesAPartialFileThatOpens) {
  // catenary.toml from the straight chord at 3x the explicit stability limit, a row a step (as
  // in run_command_test): it blows up within a few dozen rows.
  const std::string base_text = ReadText(fs::path(CABLEFILM_SOURCE_DIR) / "scenes/catenary.toml");
  const fs::path probe = dir_ / "probe.toml";
  std::ofstream(probe, std::ios::binary) << base_text;
  const double limit = ComputeStabilityLimit(LineOf(LoadScene(probe.string()))).time_step;
  const std::string dt = Format("%.17g", 3.0 * limit);
  std::string text = Replace(base_text, "time_step = \"auto\"",
                             "integrator = \"explicit\"\ntime_step = " + dt);
  text = Replace(text, "interval = 0.05", "interval = " + dt);
  const fs::path scene = dir_ / "blowup.toml";
  std::ofstream(scene, std::ios::binary) << text;
  RunOptions opt;
  opt.out_dir = (dir_ / "out").string();
  opt.film = 0;
  std::string message;
  try {
    RunCommand(scene.string(), opt);
  } catch (const std::exception& e) {
    message = e.what();
  }
  ASSERT_NE(message.find("results.partial.nc"), std::string::npos) << message;
  const fs::path out = dir_ / "out";
  EXPECT_FALSE(fs::exists(out / "results.nc"));
  ASSERT_TRUE(fs::exists(out / "results.partial.nc"));
  ExpectNoTemporaryFiles(out);
  const auto csv = ReadCsv(out / "timeseries.partial.csv");
  NcFile nc(out / "results.partial.nc");
  EXPECT_EQ(nc.Dim("time"), csv.size() - 1);
  EXPECT_GT(nc.Dim("time"), 1u);
  const std::vector<double> tension = nc.Values("tension");
  const size_t links = nc.Dim("link");
  for (size_t r = 0; r + 1 < csv.size(); ++r)
    EXPECT_EQ(Format("%.10g", *std::max_element(tension.begin() + r * links,
                                                tension.begin() + (r + 1) * links)),
              csv[r + 1][6]);
}

TEST_F(NetcdfResultsTest, CompareWritesBothModelsAndEarlierResultsGo) {
  const std::string scene = ShortP63("1.0");
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  // An earlier run's results, listed in the folder's ledger as that run listed them.
  std::ofstream ledger(out / OutputLedger::kFileName);
  for (const char* stale : {"results.nc", "results.partial.nc", "results_inextensible.partial.nc"}) {
    std::ofstream(out / stale) << "stale result of an earlier run";
    ledger << stale << "\n";
  }
  ledger.close();
  RunOptions opt;
  opt.out_dir = out.string();
  ASSERT_EQ(CompareCommand(scene, opt), 0);
  EXPECT_FALSE(fs::exists(out / "results.partial.nc"));
  EXPECT_FALSE(fs::exists(out / "results_inextensible.partial.nc"));
  ExpectNoTemporaryFiles(out);
  for (const auto& [file, model, series] :
       {std::tuple{"results.nc", "elastic", "timeseries.csv"},
        std::tuple{"results_inextensible.nc", "inextensible", "timeseries_inextensible.csv"}}) {
    NcFile nc(out / file);
    EXPECT_EQ(nc.Attr(NC_GLOBAL, "model"), model);
    const auto csv = ReadCsv(out / series);
    ASSERT_EQ(nc.Dim("time"), csv.size() - 1) << file;
    const std::vector<double> tension = nc.Values("tension");
    for (size_t r = 0; r + 1 < csv.size(); ++r)
      EXPECT_EQ(Format("%.10g", *std::max_element(tension.begin() + r * 60,
                                                  tension.begin() + (r + 1) * 60)),
                csv[r + 1][6])
          << file << " row " << r;
  }
}

}  // namespace
}  // namespace cablefilm

namespace cablefilm {
namespace {

// The column of a CSV (header row first) by name; -1 if none.
int Column(const std::vector<std::vector<std::string>>& rows, const std::string& name) {
  const auto& h = rows.front();
  const auto it = std::find(h.begin(), h.end(), name);
  return it == h.end() ? -1 : static_cast<int>(it - h.begin());
}

// Issue 21 item 5: a material's minimum_breaking_load and the utilisation tension / MBL in the
// result files. Case P63's line is 30 links of wire from the anchor, then 30 of nylon to the
// fairlead, where the tension is largest; the wire given a small MBL (10 kN) and the nylon a
// large one (100 kN), the largest utilisation is in the wire, not at the largest tension. The
// truth is computed here from results.nc's tensions and the MBLs the test gave, not from
// anything the run computed about utilisation.
TEST_F(NetcdfResultsTest, UtilisationOfAMaterialMixAgainstTheResultFiles) {
  const double mbl_wire = 10e3, mbl_nylon = 100e3;  // [N]
  std::string text = ReadText(ShortP63("5.0"));
  text = Replace(text, "name = \"wire\"", "name = \"wire\"\nminimum_breaking_load = 10e3");
  text = Replace(text, "name = \"nylon\"", "name = \"nylon\"\nminimum_breaking_load = 100e3");
  const fs::path scene = dir_ / "p63_mbl.toml";
  std::ofstream(scene, std::ios::binary) << text;
  RunOptions opt;
  opt.out_dir = (dir_ / "out").string();
  ASSERT_EQ(RunCommand(scene.string(), opt), 0);
  const fs::path out = dir_ / "out";

  const NcFile nc(out / "results.nc");
  const size_t rows = nc.Dim("time"), links = nc.Dim("link");
  ASSERT_EQ(links, 60u);
  EXPECT_EQ(nc.Dims("minimum_breaking_load"), "link");
  EXPECT_EQ(nc.Attr("minimum_breaking_load", "units"), "N");
  const std::vector<double> mbl = nc.Values("minimum_breaking_load"), T = nc.Values("tension");
  for (size_t j = 0; j < links; ++j) EXPECT_EQ(mbl[j], j < 30 ? mbl_wire : mbl_nylon) << j;

  const auto csv = ReadCsv(out / "timeseries.csv");
  const int col = Column(csv, "utilisation_max");
  ASSERT_EQ(col, 16);  // the last column, after link_max and the end loads
  ASSERT_EQ(csv.size(), rows + 1);
  double best = -1, best_t = 0;
  size_t best_link = 0, best_row = 0;
  size_t peak_link = 0;
  double peak = -1;
  for (size_t r = 0; r < rows; ++r) {
    double u = -1;
    for (size_t j = 0; j < links; ++j) {
      const double tension = T[r * links + j];
      const double uj = tension / (j < 30 ? mbl_wire : mbl_nylon);
      if (uj > u) u = uj;
      if (uj > best) best = uj, best_link = j, best_row = r;
      if (tension > peak) peak = tension, peak_link = j;
    }
    // The CSV prints 10 significant digits: within 1e-9 of the value.
    EXPECT_NEAR(std::stod(csv[r + 1][static_cast<size_t>(col)]), u, 1e-9 * u) << r;
  }
  best_t = std::stod(csv[best_row + 1][0]);
  std::printf("largest utilisation %.6g (link %zu, t = %.4g s); largest tension %.6g N (link %zu, "
              "utilisation %.4g)\n",
              best, best_link, best_t, peak, peak_link, peak / mbl_nylon);
  EXPECT_LT(best_link, 30u);   // in the wire
  EXPECT_GE(peak_link, 30u);   // the largest tension in the nylon
  EXPECT_GT(best, peak / mbl_nylon);

  const std::string report = ReadText(out / "run_report.toml");
  RunSummary s;
  ASSERT_TRUE(ReadRunReport((out / "run_report.toml").string(), &s)) << report;
  EXPECT_NEAR(s.utilisation, best, 1e-9 * best);
  EXPECT_EQ(s.utilisation_link, static_cast<int>(best_link));
  EXPECT_NEAR(s.utilisation_t, best_t, 1e-9);
  EXPECT_NEAR(s.utilisation_tension, best * mbl_wire, 1e-9 * best * mbl_wire);
  EXPECT_EQ(s.utilisation_mbl, mbl_wire);
  EXPECT_EQ(s.utilisation_material, "wire");
  EXPECT_EQ(s.peak_link, static_cast<int>(peak_link));

  // Without a breaking load nothing changes: no column, no variable, no key.
  const fs::path plain = dir_ / "plain";
  opt.out_dir = plain.string();
  ASSERT_EQ(RunCommand(ShortP63("1.0"), opt), 0);
  EXPECT_EQ(Column(ReadCsv(plain / "timeseries.csv"), "utilisation_max"), -1);
  const NcFile nc_plain(plain / "results.nc");
  int var = -1;
  EXPECT_NE(nc_inq_varid(nc_plain.id(), "minimum_breaking_load", &var), NC_NOERR);
  EXPECT_EQ(ReadText(plain / "run_report.toml").find("utilisation"), std::string::npos);
}

}  // namespace
}  // namespace cablefilm

namespace cablefilm {
namespace {

// A system's run_report.toml gives the largest utilisation over its lines and which line: the
// truth is the largest utilisation_max of every line's own timeseries.csv (spread_mooring's
// four chain lines, MBL 6 MN, 10 s).
TEST_F(NetcdfResultsTest, SystemUtilisationIsTheLargestOfItsLines) {
  const double mbl = 6e6;  // [N]
  std::string text = ReadText(fs::path(CABLEFILM_SOURCE_DIR) / "scenes/spread_mooring.toml");
  text = Replace(text, "name = \"chain\"", "name = \"chain\"\nminimum_breaking_load = 6e6");
  text = Replace(Replace(text, "duration = 60.0", "duration = 10.0"), "film = true", "film = false");
  const fs::path scene = dir_ / "spread_mbl.toml";
  std::ofstream(scene, std::ios::binary) << text;
  RunOptions opt;
  opt.out_dir = (dir_ / "out").string();
  ASSERT_EQ(RunCommand(scene.string(), opt), 0);
  const fs::path out = dir_ / "out";
  double best = -1;
  std::string best_line;
  for (const char* line : {"leg1_lower", "leg1_upper", "leg2", "leg3"}) {
    const auto csv = ReadCsv(out / "lines" / line / "timeseries.csv");
    const int col = Column(csv, "utilisation_max"), tmax = Column(csv, "tension_max");
    ASSERT_GE(col, 0) << line;
    for (size_t r = 1; r < csv.size(); ++r) {
      const double u = std::stod(csv[r][static_cast<size_t>(col)]);
      // One material: the utilisation is the largest tension over the MBL (10 digits).
      EXPECT_NEAR(u, std::stod(csv[r][static_cast<size_t>(tmax)]) / mbl, 1e-9 * u) << line << r;
      if (u > best) best = u, best_line = line;
    }
  }
  RunSummary s;
  ASSERT_TRUE(ReadRunReport((out / "run_report.toml").string(), &s));
  std::printf("system: largest utilisation %.6g in line %s (report: %.6g in %s)\n", best,
              best_line.c_str(), s.utilisation, s.utilisation_line.c_str());
  EXPECT_NEAR(s.utilisation, best, 1e-9 * best);
  EXPECT_EQ(s.utilisation_line, best_line);
  EXPECT_EQ(s.utilisation_material, "chain");
  EXPECT_EQ(s.utilisation_mbl, mbl);
  EXPECT_EQ(s.peak_line, best_line);  // one material: at the peak tension
}

}  // namespace
}  // namespace cablefilm
