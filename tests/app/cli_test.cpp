// Issue 11: the program as a user drives it, through its command line: every bad input is
// answered with a message and a status (never an abort), before anything is simulated when
// the input alone tells; messages name the scene and print input text escaped.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cmath>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../core/text_support.h"

namespace {

namespace fs = std::filesystem;

using cablefilm_test::ReadText;
using cablefilm_test::Replace;

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

struct Outcome {
  int status = -1;
  std::string out, err;
};

class CommandLine : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cablefilm_cli_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // catenary.toml (2 s, no film) with `from` replaced by `to`, written as `name`.
  std::string Scene(const std::string& name, const std::string& from = "",
                    const std::string& to = "") {
    std::string text = ReadText(fs::path(CABLEFILM_SOURCE_DIR) / "scenes" / "catenary.toml");
    if (!from.empty()) text = Replace(text, from, to);
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  // Runs cablefilm with `args` (already quoted for the shell), in the test's folder, with the
  // environment's assignments `env` ("NAME=value ...", quoted) when given.
  Outcome Run(const std::string& args, const std::string& env = "") {
    const std::string cmd = "cd '" + dir_.string() + "' || exit 99\n" +
                            "exec >stdout.txt 2>stderr.txt\n" + env + " '" +
                            CABLEFILM_BINARY_DIR + "/cablefilm' " + args;
    const int rc = std::system(cmd.c_str());
    Outcome o;
    o.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc);
    o.out = ReadText(dir_ / "stdout.txt");
    o.err = ReadText(dir_ / "stderr.txt");
    return o;
  }
  fs::path dir_;
};

// Defect 1: exit 134 (std::bad_optional_access) in check and run.
TEST_F(CommandLine, IntegerBeyond2To53IsAMessage) {
  const std::string scene = Scene("big.toml", "fluid_density = 0.0",
                                  "fluid_density = 0.0\ncurrent = 9007199254740993");
  for (const char* command : {"check", "run --no-film --out out"}) {
    const Outcome o = Run(std::string(command) + " big.toml");
    EXPECT_EQ(o.status, 1) << command << ": " << o.err;
    EXPECT_NE(o.err.find("big.toml:8: environment.current"), std::string::npos) << o.err;
  }
}

// Defect 3: duration = 1e18 simulated 0 s with exit status 0.
TEST_F(CommandLine, RunThatWouldDoNothingIsRefused) {
  Scene("long.toml", "duration = 2.0", "duration = 1e18");
  for (const char* command : {"check", "run --no-film --out out"}) {
    const Outcome o = Run(std::string(command) + " long.toml");
    EXPECT_EQ(o.status, 1) << command;
    EXPECT_NE(o.err.find("simulation.duration"), std::string::npos) << o.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// Defect 5: --size 99999999998x16 overflowed to a width of 1.2e9 (std::bad_alloc) and
// --size 65536x65536 aborted under a memory limit: refused with the stated pixel limits.
TEST_F(CommandLine, FilmSizeHasLimits) {
  Scene("s.toml");
  for (const char* size : {"99999999998x16", "65536x65536", "7682x4320", "640x481", "640x480x",
                           "-640x480", "0x0", "x"}) {
    const Outcome o = Run(std::string("run s.toml --out out --size ") + size);
    EXPECT_EQ(o.status, 2) << size;
    EXPECT_NE(o.err.find("--size: expected WxH"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("16x16 to 7680x4320"), std::string::npos) << o.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// Defect 6: --fps inf was accepted and failed late; fps 1e12, 1e300, 1e-300 failed after the
// whole simulation with a libx264 message. Options are checked before anything runs.
TEST_F(CommandLine, FilmRateOptionsHaveLimits) {
  Scene("s.toml");
  for (const char* fps : {"inf", "nan", "1e12", "1e300", "1e-300", "0", "241", "30fps"}) {
    const Outcome o = Run(std::string("run s.toml --out out --fps ") + fps);
    EXPECT_EQ(o.status, 2) << fps;
    EXPECT_NE(o.err.find("--fps: expected a number from 1 to 240"), std::string::npos) << o.err;
  }
  for (const char* bad : {"--speed inf", "--speed -1", "--tension-range 0,inf",
                          "--tension-range 5,1", "--tension-range 0,1,", "--colormap jet"}) {
    const Outcome o = Run(std::string("run s.toml --out out ") + bad);
    EXPECT_EQ(o.status, 2) << bad << ": " << o.err;
  }
  // A speed that leaves the film without a frame (or with too many) needs the scene: refused
  // with it, before the simulation (no output folder). (Without a film it does not matter.)
  for (const char* speed : {"1e-300", "1e6"}) {
    const Outcome o = Run(std::string("run s.toml --out out --film --speed ") + speed);
    EXPECT_EQ(o.status, 1) << speed;
    EXPECT_NE(o.err.find("s.toml: --speed:"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("expected 1 to 1e6 frames"), std::string::npos) << o.err;
    EXPECT_EQ(o.out.find("simulated"), std::string::npos) << o.out;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  // The scene's own rate: `check` refuses what `run` would.
  Scene("fps.toml", "film = false", "film = true\n\n[film]\nfps = 1e12");
  const Outcome o = Run("check fps.toml");
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("film.fps: expected a number of frames per second from 1 to 240"),
            std::string::npos)
      << o.err;
}

// Defect 7: a scene path that is a directory said "material: missing".
TEST_F(CommandLine, SceneThatIsADirectory) {
  fs::create_directories(dir_ / "scene.toml");
  const Outcome o = Run("check scene.toml");
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("scene.toml: is a directory"), std::string::npos) << o.err;
}

// Defect 7: elastic ends more than twice the cable's length apart passed `check` with a
// warning, then `run` reported a "numerical blow-up at t = 0"; both refuse it now.
TEST_F(CommandLine, CheckRefusesWhatRunWouldBlowUpOn) {
  Scene("far.toml", "position = [80.0, 20.0]", "position = [210.0, 0.0]");
  for (const char* command : {"check", "run --no-film --out out"}) {
    const Outcome o = Run(std::string(command) + " far.toml");
    EXPECT_EQ(o.status, 1) << command;
    EXPECT_NE(o.err.find("far.toml: ends.end.position: the ends are 210 m apart"),
              std::string::npos)
        << o.err;
    EXPECT_EQ(o.err.find("blow-up at t = 0"), std::string::npos) << o.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// Defect 7: errors found while running never named the scene file.
TEST_F(CommandLine, ErrorsWhileRunningNameTheScene) {
  // Explicit steps far above the stability limit (1.1e-3 s): a blow-up while running.
  Scene("blowup.toml", "time_step = \"auto\"", "integrator = \"explicit\"\ntime_step = 0.01");
  const Outcome o = Run("run blowup.toml --no-film --out out");
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("cablefilm: error: blowup.toml: numerical blow-up"), std::string::npos)
      << o.err;
}

// Defect 7: film errors were printed twice (by the film writer's destructor, then by main).
TEST_F(CommandLine, FilmErrorPrintedOnce) {
#ifndef CABLEFILM_HAS_FILM
  GTEST_SKIP() << "built without the renderer";
#endif
  Scene("film.toml", "duration = 2.0", "duration = 20.0");
  // Frame 300 of 601 cannot be written: once the film has begun (earlier results are cleared
  // at the start), a folder takes its name.
  const Outcome o = Run(
      "run film.toml --out out --film --frames --size 320x240 & "
      "for i in $(seq 3000); do [ -e out/frames/frame_000001.png ] && break; sleep 0.01; done; "
      "mkdir -p out/frames/frame_000300.png/x; wait $!");
  EXPECT_EQ(o.status, 1) << o.err;
  EXPECT_EQ(Count(o.err, "frame_000300.png: Is a directory"), 1u) << o.err;
  EXPECT_NE(o.err.find("cablefilm: error: film.toml: "), std::string::npos) << o.err;
}

// Defect 8: a title's control characters went raw to the terminal; messages echoed escape
// sequences from the input.
TEST_F(CommandLine, UntrustedTextIsEscaped) {
  Scene("title.toml", "title = \"Elastic catenary between fixed points\"",
        "title = \"evil \\u001b[2J\\u001b]0;pwned\\u0007 \\u009b31m\"");
  const Outcome o = Run("check title.toml");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out.find('\x1b'), std::string::npos);
  EXPECT_EQ(o.out.find('\x07'), std::string::npos);
  EXPECT_EQ(o.out.find("\xC2\x9B"), std::string::npos);
  EXPECT_NE(o.out.find("\"evil \\x1B[2J\\x1B]0;pwned\\x07 \\u{009B}31m\""), std::string::npos)
      << o.out;
  // In an option, an unknown key and a file name.
  const Outcome opt = Run("run title.toml --colormap \"$(printf '\\033[31m')\"");
  EXPECT_EQ(opt.status, 2);
  EXPECT_EQ(opt.err.find('\x1b'), std::string::npos);
  EXPECT_NE(opt.err.find("got \"\\x1B[31m\""), std::string::npos) << opt.err;
  Scene("key.toml", "[output]", "[output]\n\"\\u001b[2J\" = 1");
  const Outcome key = Run("check key.toml");
  EXPECT_EQ(key.status, 1);
  EXPECT_EQ(key.err.find('\x1b'), std::string::npos);
  EXPECT_NE(key.err.find("output.\\x1B[2J: unknown key"), std::string::npos) << key.err;
}

}  // namespace

namespace {

// Issue 12: --version, and --help for the program and for each command, on stdout, status 0.
TEST_F(CommandLine, VersionAndHelp) {
  const Outcome version = Run("--version");
  EXPECT_EQ(version.status, 0) << version.err;
  EXPECT_EQ(version.out.rfind("cablefilm " CABLEFILM_VERSION, 0), 0u) << version.out;
  EXPECT_EQ(Count(version.out, "\n"), 1u) << version.out;

  for (const char* args : {"--help", "-h", "help"}) {
    const Outcome o = Run(args);
    EXPECT_EQ(o.status, 0) << args;
    EXPECT_TRUE(o.err.empty()) << args << ": " << o.err;
    for (const char* command : {"run", "compare", "check", "live", "--version"})
      EXPECT_NE(o.out.find(command), std::string::npos) << args << " lacks " << command;
  }
  const std::vector<std::string> film_options = {
      "--out DIR", "--no-film", "--film", "--frames", "--size WxH", "--fps N", "--speed X",
      "--colormap NAME", "--tension-range MIN,MAX", "--shaders DIR"};
  const std::vector<std::string> live_options = {
      "--port N", "--bind ADDR", "--size WxH", "--fps N", "--speed X", "--colormap NAME",
      "--out DIR", "--shaders DIR"};
  struct Help {
    std::string command;
    std::vector<std::string> options;
  };
  std::vector<Help> helps = {{"run", film_options}, {"compare", film_options}, {"check", {}}};
#ifdef CABLEFILM_HAS_FILM
  helps.push_back({"live", live_options});
#endif
  for (const Help& h : helps) {
    for (const std::string& args : {h.command + " --help", h.command + " -h", "help " + h.command}) {
      const Outcome o = Run(args);
      EXPECT_EQ(o.status, 0) << args << ": " << o.err;
      EXPECT_NE(o.out.find("Usage: cablefilm " + h.command + " [OPTIONS] SCENE"),
                std::string::npos)
          << args << ":\n" << o.out;
      for (const std::string& option : h.options)
        EXPECT_NE(o.out.find("  " + option + " "), std::string::npos)
            << args << " lacks " << option << ":\n" << o.out;
      if (h.options.empty()) {
        EXPECT_EQ(o.out.find("--out"), std::string::npos) << o.out;
      }
    }
  }
  EXPECT_FALSE(fs::exists(dir_ / "output"));
}

// Issue 12: a bad option is refused with status 2 before anything runs (no output folder, nothing
// on stdout), by a message that names the option and points to the command's --help.
TEST_F(CommandLine, BadOptionsAreNamed) {
  Scene("s.toml");
  struct Case {
    std::string args, message;
  };
  std::vector<Case> cases = {
      {"", "cablefilm: missing command"},
      {"frobnicate s.toml", "cablefilm: unknown command \"frobnicate\""},
      {"--out x run s.toml", "unknown option \"--out\" (options go after the command)"},
      {"s.toml run", "unknown command \"s.toml\""},
      {"check", "SCENE is required"},
      {"check s.toml --out out", "unknown option \"--out\" for check"},
      {"check s.toml s.toml", "more than one scene given"},
  };
  for (const std::string command : {"run", "compare"}) {
    const std::string base = command + " s.toml --out out ";
    for (const Case& c : std::vector<Case>{
             {"--size 17x16", "--size: expected WxH"},
             {"--fps 0", "--fps: expected a number from 1 to 240"},
             {"--speed 0", "--speed: expected a number above 0"},
             {"--colormap jet", "--colormap: expected one of viridis"},
             {"--tension-range 5,1", "--tension-range: expected MIN,MAX"},
             {"--shaders nowhere", "--shaders: expected a folder of GLSL shaders, got \"nowhere\""},
             {"--size", "--size: missing value (expected WxH)"},
             {"--film-window 5,1", "--film-window: expected peak:SECONDS"},
             {"--film-window peak:0", "--film-window: expected peak:SECONDS"},
             {"--fps 30 --bogus", "unknown option \"--bogus\" for " + command},
             {"--port 80", "unknown option \"--port\" for " + command},
         })
      cases.push_back({base + c.args, c.message});
    cases.push_back({command + " --out out", "SCENE is required"});
  }
#ifdef CABLEFILM_HAS_FILM
  for (const Case& c : std::vector<Case>{
           {"--port 65536", "--port: expected a port number 0..65535, got \"65536\""},
           {"--port 80x", "--port: expected a port number"},
           {"--fps 121", "--fps: expected a number from 1 to 120"},
           {"--speed 11", "--speed: expected a number from 0.1 to 10"},
           {"--size 8x8", "--size: expected WxH"},
           {"--colormap jet", "--colormap: expected one of"},
           {"--bind", "--bind: missing value"},
           {"--no-film", "unknown option \"--no-film\" for live"},
       })
    cases.push_back({"live s.toml --out out " + c.args, c.message});
#endif
  for (const Case& c : cases) {
    const Outcome o = Run(c.args);
    EXPECT_EQ(o.status, 2) << c.args << ": " << o.err;
    EXPECT_NE(o.err.find(c.message), std::string::npos) << c.args << ": " << o.err;
    EXPECT_NE(o.err.find("--help' for the options"), std::string::npos) << c.args << ": " << o.err;
    EXPECT_TRUE(o.out.empty()) << c.args << ": " << o.out;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  EXPECT_FALSE(fs::exists(dir_ / "output"));
}

// Issue 12: options as before: the last of a repeated option wins; --frames makes the film.
TEST_F(CommandLine, RepeatedOptionsTakeTheLast) {
  Scene("s.toml");
  const Outcome o = Run("run s.toml --out out --no-film --fps 999 --fps 30 --out out2");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(fs::exists(dir_ / "out2" / "timeseries.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "out2" / "film.mp4"));
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// Issue 22 item 1: a full disk (tests/app/full_disk_shim.cpp: writes to the chosen temporary
// files fail with ENOSPC past a budget) killed the run with SIGSEGV after its message when
// results.nc's close failed, or when the CSV failed and the NetCDF file's close after it: HDF5's
// exit handler closed the file the failed close had freed. Exit 1 with the message, nothing
// left under a final name or a temporary one.
TEST_F(CommandLine, FullDiskIsAnErrorNotACrash) {
  const std::string scene = Scene("s.toml");
  const std::string shim = std::string("LD_PRELOAD='") + CABLEFILM_FULL_DISK_SHIM +
                           "' ASAN_OPTIONS=\"$ASAN_OPTIONS:verify_asan_link_order=0\" ";
  // The bytes the run writes to results.nc (fewer than the file's size: the unused rows of its
  // last chunks are a hole), counted by the shim with room for all.
  const fs::path report = dir_ / "written.txt";
  const Outcome whole = Run("run --no-film --out whole s.toml",
                            shim + "CABLEFILM_TEST_FULL_DISK='results.nc.tmp:1000000000' "
                                   "CABLEFILM_TEST_FULL_DISK_REPORT='" + report.string() + "' ");
  ASSERT_EQ(whole.status, 0) << whole.err;
  long long nc_size = 0;
  std::ifstream(report) >> nc_size;
  ASSERT_GT(nc_size, 0);
  ASSERT_LE(nc_size, static_cast<long long>(fs::file_size(dir_ / "whole" / "results.nc")));
  const std::string nc = "results.nc.tmp:", csv = ",timeseries.csv.tmp:";
  struct Case {
    std::string full;  // CABLEFILM_TEST_FULL_DISK: the files and the bytes each may take
    std::string message;
  };
  const std::vector<Case> cases{
      // Only the last writes of the close fail (the report's case: its last 4 kB, the file's
      // definitions), or the chunks as the run writes them, or every write. (A disk full
      // within the very last bytes, the superblock the close rewrites, still crashes in
      // netCDF's close: it lists the file's objects after HDF5 1.10 has freed the file.)
      {nc + std::to_string(nc_size - 4096), "results.nc.tmp"},
      {nc + std::to_string(nc_size / 2), "results.nc.tmp"},
      {nc + "0", "results.nc.tmp"},
      // The CSV fails first; the NetCDF file, closed as the run unwinds, fails too.
      {nc + std::to_string(nc_size) + csv + "0", "timeseries.csv.tmp"},
      {nc + std::to_string(nc_size) + csv + "500", "timeseries.csv.tmp"},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string out = "out" + std::to_string(k++);
    const std::string env = shim + "CABLEFILM_TEST_FULL_DISK='" + c.full + "' ";
    const std::string& what = c.full;
    const Outcome o = Run("run --no-film --out " + out + " s.toml", env);
    EXPECT_EQ(o.status, 1) << what << ": " << o.err;
    EXPECT_NE(o.err.find("s.toml"), std::string::npos) << what << ": " << o.err;
    EXPECT_NE(o.err.find(c.message), std::string::npos) << what << ": " << o.err;
    // The system's reason, not only HDF5's "HDF error" or "Permission denied".
    EXPECT_TRUE(o.err.find("No space left on device") != std::string::npos ||
                o.err.find("disk full") != std::string::npos)
        << what << ": " << o.err;
    EXPECT_FALSE(fs::exists(dir_ / out / "results.nc")) << what;
    for (const auto& entry : fs::directory_iterator(dir_ / out))
      EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos)
          << what << ": " << entry.path();
  }
}

// Issue 22 item 4: two runs into one --out left a mixed folder (one's equilibrium beside the
// other's time series), both exiting 0. A run holds .cablefilm.lock (flock) in its folder; a
// second is refused, naming the first one's process, before it touches the folder.
TEST_F(CommandLine, SecondRunIntoABusyFolderIsRefused) {
  Scene("s.toml");
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  std::ofstream(out / "timeseries.csv") << "the other run's rows\n";
  // Another run holding the folder, as a run holds it: the lock, and its process id inside.
  const int fd = ::open((out / ".cablefilm.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string holder = std::to_string(::getpid());
  ASSERT_EQ(::write(fd, (holder + "\n").data(), holder.size() + 1),
            static_cast<ssize_t>(holder.size() + 1));
  for (const char* command : {"run --no-film", "compare --no-film"}) {
    const Outcome o = Run(std::string(command) + " --out out s.toml");
    EXPECT_EQ(o.status, 1) << command << ": " << o.err;
    EXPECT_NE(o.err.find("s.toml: the output folder out is in use by another cablefilm run "
                         "(process " + holder + ")"),
              std::string::npos)
        << command << ": " << o.err;
    EXPECT_EQ(ReadText(out / "timeseries.csv"), "the other run's rows\n") << command;
    EXPECT_FALSE(fs::exists(out / "equilibrium.csv")) << command;
  }
  const Outcome sweep = Run("sweep --out out --set environment.gravity=9,10 s.toml");
  EXPECT_EQ(sweep.status, 1) << sweep.err;
  EXPECT_NE(sweep.err.find("the sweep folder out is in use by another cablefilm run (process " +
                           holder + ")"),
            std::string::npos)
      << sweep.err;
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
  // Let go (as a run that ends, or is killed, lets go): the file left behind is taken over, and
  // a run that ends removes it.
  ::close(fd);
  const Outcome after = Run("run --no-film --out out s.toml");
  EXPECT_EQ(after.status, 0) << after.err;
  EXPECT_TRUE(fs::exists(out / "equilibrium.csv"));
  EXPECT_NE(ReadText(out / "timeseries.csv"), "the other run's rows\n");
  EXPECT_FALSE(fs::exists(out / ".cablefilm.lock"));
}

// The same with two real runs: the first (long) holds the folder while it runs.
TEST_F(CommandLine, TwoRunsIntoOneFolder) {
  Scene("long.toml", "duration = 2.0", "duration = 1e5");
  Scene("s.toml");
  const fs::path lock = dir_ / "out" / ".cablefilm.lock";
  const pid_t first = ::fork();
  ASSERT_GE(first, 0);
  if (first == 0) {
    const std::string cmd = "cd '" + dir_.string() + "' && exec '" + CABLEFILM_BINARY_DIR +
                            "/cablefilm' run --no-film --out out long.toml >first.txt 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Until the first run has locked the folder and written its process id (a condition, not a
  // time; the first run cannot end by itself before the test stops it).
  const std::string pid = std::to_string(first);
  int status = 0;
  while (ReadText(lock) != pid + "\n") {
    ASSERT_EQ(::waitpid(first, &status, WNOHANG), 0) << ReadText(dir_ / "first.txt");
    ::usleep(10000);
  }
  const Outcome second = Run("run --no-film --out out s.toml");
  EXPECT_EQ(second.status, 1) << second.err;
  EXPECT_NE(second.err.find("in use by another cablefilm run (process " + pid + ")"),
            std::string::npos)
      << second.err;
  ::kill(first, SIGINT);
  ASSERT_EQ(::waitpid(first, &status, 0), first);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 130) << ReadText(dir_ / "first.txt");
  EXPECT_TRUE(fs::exists(dir_ / "out" / "timeseries.partial.csv"));  // the first run's, alone
  EXPECT_FALSE(fs::exists(lock));
}

// Issue 22 item 5: the line's own load stretching a link past twice its rest length in the
// static equilibrium: `check` said ok and `run` stopped at t = 0 with a blow-up naming no key.
// Both refuse it now, alike, naming the key at fault; a system's line too.
TEST_F(CommandLine, EquilibriumStretchedPastTwiceIsRefusedByCheckAndRun) {
  auto edited = [&](const char* scene, const std::string& from, const std::string& to,
                    const char* name) {
    const std::string text = ReadText(fs::path(CABLEFILM_SOURCE_DIR) / "scenes" / scene);
    std::ofstream(dir_ / name, std::ios::binary) << Replace(text, from, to);
  };
  // A 2e5 kg weight on the hanging chain (EA = 1 MN): the weight's mass.
  edited("hanging_chain.toml", "[initial]", "[[cable.weight]]\nat = 10.0\nmass = 2e5\n\n[initial]",
         "heavy.toml");
  // P63's wire with E = 16 Pa: the material's modulus (the weight is the same as ever).
  edited("polachek1963.toml", "youngs_modulus = 9.0e10", "youngs_modulus = 16", "soft.toml");
  // A system's line (a MoorDyn file's soft spring, found so): 200 kg on 1 m of EA = 1 kN in
  // vacuum stretches it to 1 + 200 x 9.81 / 1000 = 2.96 times.
  std::ofstream(dir_ / "spring.toml", std::ios::binary) << R"([environment]
gravity = 9.81
fluid_density = 0.0
[[material]]
name = "spring"
diameter = 0.01
area = 1e-4
mass_per_length = 0.001
youngs_modulus = 1e7
[[point]]
name = "top"
position = [0.0, 0.0, 0.0]
motion = "fixed"
[[point]]
name = "bob"
position = [0.0, -1.0, 0.0]
motion = "free"
mass = 200.0
[[line]]
name = "spring"
start = "top"
end = "bob"
[[line.section]]
material = "spring"
length = 1.0
segments = 4
)";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"heavy.toml", "heavy.toml: cable.weight[0].mass: the static equilibrium at t = 0 "
                     "stretches link 0 (stations 0-1, section 0) to 2.96"},
      {"spring.toml", "spring.toml: material[0].youngs_modulus: the static equilibrium at t = 0 "
                      "stretches link 0 (stations 0-1, section 0) of line[0] (\"spring\") to "
                      "2.96"},
      {"soft.toml", "soft.toml: material[0].youngs_modulus: the static equilibrium at t = 0 "
                    "stretches link "}};
  for (const auto& [scene, message] : cases) {
    for (const std::string command : {"check", "run --no-film --out out"}) {
      const Outcome o = Run(command + " " + scene);
      EXPECT_EQ(o.status, 1) << command << " " << scene << ": " << o.out << o.err;
      EXPECT_NE(o.err.find(message), std::string::npos) << command << ": " << o.err;
      EXPECT_NE(o.err.find("expected at most 2 times"), std::string::npos) << o.err;
      EXPECT_EQ(o.err.find("blow-up at"), std::string::npos) << o.err;
    }
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / "timeseries.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "timeseries.partial.csv"));
}

// A MoorDyn file's problems found after it is read, in the scene it converts to (the statics,
// the built model's limits, a value out of the scene's range), are told at the file's row and
// column, as the MoorDyn reader tells its own: never by a scene key the file does not have.
TEST_F(CommandLine, MoorDynFileProblemsAfterItsImportNameItsRowsAndColumns) {
  // The soft spring of the test above as a MoorDyn file: 200 kg on 1 m of EA = 1 kN in vacuum.
  const std::string spring = R"(--------------------- MoorDyn Input File ---------------------
A soft spring under a heavy bob, in vacuum
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m   EA       BA/-zeta   EI     Cd    Ca    CdAx   CaAx
(name)     (m)     (kg/m)   (N)      (N-s/-)    (N-m^2) (-)  (-)   (-)    (-)
spring     0.01    0.001    1000     0          0      1.2   1.0   0.0    0.0
---------------------- POINTS ---------------------------------------
ID   Attachment   X       Y      Z       Mass   Volume   CdA    Ca
(#)  (-)          (m)     (m)    (m)     (kg)   (m^3)    (m^2)  (-)
1    Fixed        0.0     0.0    0.0     0      0        0      0
2    Free         0.0     0.0    -1.0    200    0        0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA   AttachB   UnstrLen   NumSegs   LineOutputs
(#)  (name)     (#)       (#)       (m)        (-)       (-)
1    spring     1         2         1.0        4         -
---------------------- OPTIONS --------------------------------------
9.81      g         gravity (m/s^2)
0.0       rho       vacuum
100       WtrDpth   water depth (m)
------------------------- need this line ----------------------------
)";
  std::ofstream(dir_ / "spring.txt", std::ios::binary) << spring;
  // The bob held 3 m below a 1 m line: the ends alone stretch it three times.
  std::ofstream(dir_ / "far.txt", std::ios::binary)
      << Replace(spring, "2    Free         0.0     0.0    -1.0    200",
                 "2    Fixed        0.0     0.0    -3.0    0  ");
  // EA = 1e-6 N on 0.01 m: E = 0.0127 Pa, below the scene's 1 Pa.
  std::ofstream(dir_ / "tiny.txt", std::ios::binary)
      << Replace(spring, "0.001    1000     0", "0.001    1e-6     0");
  const std::vector<std::pair<std::string, std::string>> cases{
      {"spring.txt",
       "spring.txt:6: LINE TYPES row 1, column EA: the static equilibrium at t = 0 stretches "
       "link 0 (stations 0-1, section 0) of LINES row 1 (\"1\") to 2.96"},
      {"spring.txt", "a stiffer material (LINE TYPES row 1, column EA = 1000 N of \"spring\")"},
      {"far.txt", "far.txt:11: POINTS row 2, columns X, Y, Z: the ends are 3 m apart at t = 0"},
      {"tiny.txt", "tiny.txt:6: LINE TYPES row 1, column EA (the scene's "
                   "material[0].youngs_modulus): expected a positive number in Pa from 1 to "
                   "1e13, got 0.0127324"}};
  for (const auto& [scene, message] : cases) {
    for (const std::string command : {"check", "run --no-film --out out"}) {
      const Outcome o = Run(command + " " + scene);
      EXPECT_EQ(o.status, 1) << command << " " << scene << ": " << o.out << o.err;
      EXPECT_NE(o.err.find(message), std::string::npos) << command << ": " << o.err;
      if (scene == "tiny.txt") continue;  // said in the scene's unit, its key in brackets
      for (const char* key : {"material[", "line[", "point[", "cablefilm convert"})
        EXPECT_EQ(o.err.find(key), std::string::npos) << command << ": " << o.err;
    }
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / "timeseries.csv"));
}

// tests/scenes/moordyn/body_above_anchor.txt: a free body given above the anchor it hangs
// below. Newton from there cannot balance it (its one link passes through the anchor on the way); the statics' relaxation
// (core/relaxation.h) finds the equilibrium. Hand values (moordyn_convert_test,
// BodyGivenAboveItsAnchorHangsBelowIt): the body weighs (20 - 1025 x 0.004) 9.81 = 155.9 N in
// water, the rope 4 m of (8 - 1025 pi 0.05^2 / 4) 9.81 = 58.78 N/m, half of it at the body's
// station: the one link holds T = 155.9 + 2 x 58.78 = 273.5 N, 4 (1 + T / 2000) m long straight
// down from the anchor.
const std::string kBodyAboveAnchor =
    std::string(CABLEFILM_SOURCE_DIR) + "/tests/scenes/moordyn/body_above_anchor.txt";
const double kBodyWetWeight = (20.0 - 1025.0 * 0.004) * 9.81;  // [N]
const double kBodyLinkTension =
    kBodyWetWeight + 2.0 * (8.0 - 1025.0 * M_PI * 0.05 * 0.05 / 4) * 9.81;  // T [N]
const double kBodyLinkLength = 4.0 * (1.0 + kBodyLinkTension / 2000.0);     // L [m]

// The relaxation as a user meets it, with every default: `check` and `run` say where the
// equilibrium was found from, and the run starts at rest in it.
TEST_F(CommandLine, BodyGivenAboveItsAnchorIsRelaxedIntoEquilibrium) {
  fs::copy_file(kBodyAboveAnchor, dir_ / "above.txt");
  const double T = kBodyLinkTension, y = -5.0 - kBodyLinkLength;  // [N], [m]
  for (const std::string command : {"check", "run --no-film --out out"}) {
    const Outcome o = Run(command + " above.txt");
    ASSERT_EQ(o.status, 0) << command << ": " << o.out << o.err;
    EXPECT_NE(o.out.find("not reached from the scene's positions: found from where"),
              std::string::npos)
        << o.out;
  }
  // Every row of the body's track at the hand position: the run starts in the equilibrium and
  // stays there. Statics to 1e-9 of the load put it within 1e-8 m; the file's 12 digits and the
  // hand value's g (9.81 in both) leave 1e-6 m.
  std::istringstream rows(ReadText(dir_ / "out" / "body.csv"));
  std::string row;
  std::getline(rows, row);  // the header
  int count = 0;
  while (std::getline(rows, row)) {
    std::vector<std::string> cells;
    std::istringstream fields(row);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    ASSERT_GE(cells.size(), 5u) << row;
    EXPECT_NEAR(std::stod(cells[3]), y, 1e-6) << row;
    ++count;
  }
  EXPECT_EQ(count, 1801);  // 60 s (the converter's duration), a row every 1/30 s
  // The tension at rest: the report's peak and least alike, T (statics to 1e-9 of it; the
  // hand value is the same arithmetic: 1e-6 N).
  const std::string report = ReadText(dir_ / "out" / "run_report.toml");
  for (const char* key : {"peak_tension = ", "min_tension = "}) {
    const size_t at = report.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_NEAR(std::stod(report.substr(at + std::string(key).size())), T, 1e-6) << key;
  }
}

// The body tools start where `run` does: from the relaxed equilibrium (they said "do not balance
// after 100 Newton iterations" where `run` ran). At that pose the one link pivots about the
// anchor: horizontal stiffness T / L, vertical EA / l = 2000 / 4 N/m, no moment (the line ends at
// the reference point). Held at an offset d along x the link is L' = sqrt(L^2 + d^2) long and
// restores EA (L' - 4) / 4 d / L'.
TEST_F(CommandLine, BodyToolsStartFromTheRelaxedEquilibrium) {
  fs::copy_file(kBodyAboveAnchor, dir_ / "above.txt");
  const Outcome k = Run("stiffness above.txt");
  ASSERT_EQ(k.status, 0) << k.out << k.err;
  std::istringstream lines(k.out);
  std::vector<std::vector<double>> K;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream row(line);
    std::vector<double> values;
    for (double v; row >> v;) values.push_back(v);
    if (values.size() == 6 && row.eof()) K.push_back(values);
  }
  ASSERT_EQ(K.size(), 6u) << k.out;
  // Central differences of 4e-4 m of statics to 1e-9 of the 273 N load: 1e-3 N/m.
  EXPECT_NEAR(K[0][0], kBodyLinkTension / kBodyLinkLength, 1e-3) << k.out;
  EXPECT_NEAR(K[1][1], 2000.0 / 4.0, 1e-3) << k.out;
  EXPECT_NEAR(K[2][2], kBodyLinkTension / kBodyLinkLength, 1e-3) << k.out;
  EXPECT_NEAR(K[3][3], 0.0, 1e-3) << k.out;
  EXPECT_EQ(k.out.find("-0.0"), std::string::npos) << "a zero printed negative: " << k.out;

  const Outcome o = Run("offset above.txt --points 3");
  ASSERT_EQ(o.status, 0) << o.out << o.err;
  std::istringstream rows(o.out);
  std::string row;
  std::getline(rows, row);  // the header
  int count = 0;
  while (std::getline(rows, row)) {
    const double d = 0.1 * count++;  // 0 to 5 % of the 4 m line, in 3 points
    std::istringstream fields(row);
    double offset = 0, restoring = 0;
    char comma = 0;
    fields >> offset >> comma >> restoring;
    const double stretched = std::hypot(kBodyLinkLength, d);  // L' [m]
    EXPECT_NEAR(offset, d, 1e-12) << row;
    // A held one-link line has no unknowns: the file's 10 digits.
    EXPECT_NEAR(restoring, 2000.0 * (stretched - 4.0) / 4.0 * d / stretched, 1e-6) << row;
  }
  EXPECT_EQ(count, 3) << o.out;
}

// Output that never arrived was reported done, status 0: `convert X.txt > full/out.toml` left 0
// bytes, `offset ... --points 2000 > full/off.csv` a row cut in half, `convert -o /dev/full`
// said "wrote /dev/full", `stiffness` and `check` to /dev/full. Standard output that cannot be
// written is an error naming it, status 1, whatever the command.
TEST_F(CommandLine, StandardOutputThatCannotBeWrittenIsAnError) {
  fs::copy_file(kBodyAboveAnchor, dir_ / "above.txt");
  Scene("s.toml");
  // Short outputs (left in the buffer until the end) and a long one (failing as it goes).
  for (const std::string command :
       {"check s.toml", "convert above.txt", "stiffness above.txt", "offset above.txt --points 3",
        "offset above.txt --points 2000", "run s.toml --no-film --out out", "--version"}) {
    const Outcome o = Run(command + " >/dev/full");
    EXPECT_EQ(o.status, 1) << command << ": " << o.err;
    EXPECT_NE(o.err.find("cablefilm: error: cannot write standard output"), std::string::npos)
        << command << ": " << o.err;
  }
  const Outcome full = Run("check s.toml >/dev/full");
  EXPECT_NE(full.err.find("cannot write standard output: No space left on device"),
            std::string::npos)
      << full.err;
  // Given a device that takes it, as before.
  EXPECT_EQ(Run("check s.toml >/dev/null").status, 0);
}

// The same for -o FILE: a device is written in place (it cannot be renamed over) and its
// failure said. /dev/full is reached through a link in the test's folder: a regression that
// renamed over the path given must not replace the machine's /dev/full (tests may run as root).
TEST_F(CommandLine, OutputFileThatCannotBeWrittenIsAnError) {
  fs::copy_file(kBodyAboveAnchor, dir_ / "above.txt");
  fs::create_symlink("/dev/full", dir_ / "full");
  for (const std::string command :
       {"convert above.txt -o full", "offset above.txt --points 3 -o full"}) {
    const Outcome o = Run(command);
    EXPECT_EQ(o.status, 1) << command << ": " << o.err;
    EXPECT_NE(o.err.find("cannot write full: No space left on device"), std::string::npos)
        << command << ": " << o.err;
    EXPECT_EQ(o.err.find("wrote"), std::string::npos) << command << ": " << o.err;
    EXPECT_TRUE(fs::is_symlink(dir_ / "full")) << command;
    EXPECT_TRUE(fs::is_character_file(dir_ / "full")) << command;
  }
  // A device that takes it (through a link too); a link to a file, written through the link
  // (which stays).
  fs::create_symlink("/dev/null", dir_ / "null");
  EXPECT_EQ(Run("convert above.txt -o null").status, 0);
  EXPECT_TRUE(fs::is_character_file(dir_ / "null"));
  std::ofstream(dir_ / "old.toml") << "old\n";
  fs::create_symlink("old.toml", dir_ / "link.toml");
  const Outcome o = Run("convert above.txt -o link.toml");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.toml"));
  EXPECT_NE(ReadText(dir_ / "old.toml").find("[[line]]"), std::string::npos);
}

// `convert X.txt -o X.txt` and `offset S.toml -o S.toml` replaced their input with their output.
// -o naming an input, however spelled, is refused before anything is written (status 2),
// naming both; the input stays as it was.
TEST_F(CommandLine, OutputOverAnInputIsRefused) {
  fs::copy_file(kBodyAboveAnchor, dir_ / "above.txt");
  const std::string text = ReadText(dir_ / "above.txt");
  fs::create_symlink("above.txt", dir_ / "link.txt");
  fs::create_hard_link(dir_ / "above.txt", dir_ / "hard.txt");
  for (const std::string command : {"convert", "offset"}) {
    for (const std::string& out : std::vector<std::string>{
             "above.txt", "./above.txt", "link.txt", "hard.txt", (dir_ / "above.txt").string()}) {
      const Outcome o = Run(command + " above.txt -o '" + out + "'");
      EXPECT_EQ(o.status, 2) << command << " -o " << out << ": " << o.err;
      EXPECT_NE(o.err.find("-o: \"" + out + "\" is the input file \"above.txt\""),
                std::string::npos)
          << command << " -o " << out << ": " << o.err;
      EXPECT_EQ(ReadText(dir_ / "above.txt"), text) << command << " -o " << out;
    }
  }
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
  // A scene's motion table is an input too.
  const fs::path system = fs::path(CABLEFILM_SOURCE_DIR) / "tests" / "scenes" / "system";
  for (const char* name : {"turning_platform.toml", "turning_platform.csv"})
    fs::copy_file(system / name, dir_ / name);
  const std::string table = ReadText(dir_ / "turning_platform.csv");
  const Outcome o = Run("offset turning_platform.toml -o turning_platform.csv");
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_NE(o.err.find("is the input file"), std::string::npos) << o.err;
  EXPECT_EQ(ReadText(dir_ / "turning_platform.csv"), table);
  // Another file is written.
  EXPECT_EQ(Run("convert above.txt -o above.toml").status, 0);
  EXPECT_NE(ReadText(dir_ / "above.toml").find("[[line]]"), std::string::npos);
}

// `--no-film` still refused a long run for its film ("film.speed: ... 3.6e6 frames"). The frame
// count is the film's: without one nothing counts it; `check`, which has no --no-film, refuses
// what `run` would do with the scene's film.
TEST_F(CommandLine, NoFilmRunsWhatTheFilmCouldNotShow) {
  Scene("long.toml", "duration = 2.0", "duration = 120000.0");
  std::string text = ReadText(dir_ / "long.toml");
  text = Replace(text, "state = \"straight\"", "state = \"equilibrium\"");
  text = Replace(text, "interval = 0.05\nfilm = false", "interval = 1000.0\nfilm = true");
  std::ofstream(dir_ / "long.toml", std::ios::binary) << text;
  const Outcome run = Run("run long.toml --no-film --out out");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "run_report.toml"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "film.mp4"));
  for (const char* command : {"check long.toml", "run long.toml --out film"}) {
    const Outcome o = Run(command);
    EXPECT_EQ(o.status, 1) << command << ": " << o.err;
    EXPECT_NE(o.err.find("long.toml: film.speed: "), std::string::npos) << command << ": " << o.err;
    EXPECT_NE(o.err.find("3.6e6 frames"), std::string::npos) << command << ": " << o.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "film"));
}


// A system of `lines` lines, each of 2 links from an anchor to a fixed fairlead, `duration`
// seconds at a row every 0.5 s, no film.
std::string ManyLines(int lines, double duration) {
  std::ostringstream t;
  t << "[environment]\nfluid_density = 1025.0\n[[material]]\nname = \"chain\"\n"
       "diameter = 0.1\narea = 0.008\nmass_per_length = 100.0\nyoungs_modulus = 1e11\n";
  for (int i = 0; i < lines; ++i) {
    const double a = 2 * M_PI * i / lines;
    t << "[[point]]\nname = \"a" << i << "\"\nposition = [" << 500 * std::cos(a) << ", -100.0, "
      << 500 * std::sin(a) << "]\n[[point]]\nname = \"f" << i << "\"\nposition = ["
      << 20 * std::cos(a) << ", -10.0, " << 20 * std::sin(a) << "]\n";
  }
  for (int i = 0; i < lines; ++i)
    t << "[[line]]\nname = \"l" << i << "\"\nstart = \"a" << i << "\"\nend = \"f" << i
      << "\"\n[[line.section]]\nmaterial = \"chain\"\nlength = 550.0\nsegments = 2\n";
  t << "[simulation]\nduration = " << duration << "\n[output]\ninterval = 0.5\nfilm = false\n";
  return t.str();
}

// A system holds files open per line while it runs: 400 lines under `ulimit -n 1024` failed
// midway ("Too many open files") after `check` said ok, leaving the line folders begun. `check`
// and `run` refuse it alike before anything is written, with the count and the limit; the soft
// limit is raised to the hard one when that is enough; a system within the limit runs.
TEST_F(CommandLine, SystemBeyondTheOpenFileLimitIsRefusedBeforeItStarts) {
  std::ofstream(dir_ / "many.toml", std::ios::binary) << ManyLines(60, 1.0);
  const std::string refusal =
      "cablefilm: error: many.toml: line: a run of its 60 lines keeps 154 files open at once (2 "
      "a line: its timeseries.csv and results.nc; the model's points.csv and results.nc; 32 for "
      "the program itself), more than the limit on open files, 100 (ulimit -n); expected at "
      "most 33 lines under it: raise the limit (ulimit -n 154; beyond the hard limit as root) or "
      "run fewer lines\n";
  const Outcome check = Run("check many.toml", "ulimit -n 100;");
  EXPECT_EQ(check.status, 1) << check.out;
  EXPECT_EQ(check.err, refusal);
  const Outcome run = Run("run --out out many.toml", "ulimit -n 100;");
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_EQ(run.err, refusal);
  EXPECT_FALSE(fs::exists(dir_ / "out"));

  // 2 files a line and the program's own fit in 160: both say so, and it runs.
  const Outcome fits = Run("check many.toml", "ulimit -n 160;");
  EXPECT_EQ(fits.status, 0) << fits.err;
  EXPECT_NE(fits.out.find("\nok\n"), std::string::npos) << fits.out;
  const Outcome ran = Run("run --out fits many.toml", "ulimit -n 160;");
  ASSERT_EQ(ran.status, 0) << ran.err;
  for (int i = 0; i < 60; ++i) {
    const fs::path line = dir_ / "fits" / "lines" / ("l" + std::to_string(i));
    EXPECT_TRUE(fs::exists(line / "timeseries.csv")) << line;
    EXPECT_TRUE(fs::exists(line / "results.nc")) << line;
  }

  // A soft limit below the hard one is raised to it.
  rlimit limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &limit), 0);
  if (limit.rlim_max != RLIM_INFINITY && limit.rlim_max < 154) GTEST_SKIP() << "hard limit";
  const Outcome raised = Run("run --out raised many.toml", "ulimit -S -n 100;");
  EXPECT_EQ(raised.status, 0) << raised.err;
  EXPECT_TRUE(fs::exists(dir_ / "raised" / "lines" / "l59" / "results.nc"));

  // From 4096 rows each line's row maxima take a file of their own too (3 a line: 214).
  std::ofstream(dir_ / "long.toml", std::ios::binary) << ManyLines(60, 2048.0);
  const Outcome long_check = Run("check long.toml", "ulimit -n 200;");
  EXPECT_EQ(long_check.status, 1);
  EXPECT_NE(long_check.err.find("long.toml: line: a run of its 60 lines keeps 214 files open at "
                                "once (3 a line: its timeseries.csv, results.nc and the temporary "
                                "file of its row maxima (from 4096 rows); "),
            std::string::npos)
      << long_check.err;
  EXPECT_NE(long_check.err.find("expected at most 55 lines under it"), std::string::npos)
      << long_check.err;
}

}  // namespace
