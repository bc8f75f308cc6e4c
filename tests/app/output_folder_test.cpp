// What runs leave in their output folder, through the program itself (its results.nc and film
// are written by modules it loads): each run removes what the run before it wrote, whatever
// its layout, and never a file or folder of the user's.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "../core/text_support.h"
#include "io/output_ledger.h"

namespace cablefilm {
namespace {

namespace fs = std::filesystem;
using cablefilm_test::ReadText;
using cablefilm_test::Replace;

class OutputFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cablefilm_output_folder_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A shipped scene cut to 2 s, written as `name`.
  std::string Scene(const std::string& shipped, const std::string& from, const std::string& name) {
    const std::string text =
        ReadText(fs::path(CABLEFILM_SOURCE_DIR) / "scenes" / (shipped + ".toml"));
    std::ofstream(dir_ / name, std::ios::binary) << Replace(text, from, "duration = 2.0");
    return name;
  }
  int Run(const std::string& args) {
    const std::string cmd = "cd '" + dir_.string() + "' && exec >out.txt 2>err.txt '" +
                            CABLEFILM_BINARY_DIR + "/cablefilm' " + args;
    const int rc = std::system(cmd.c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc);
  }
  std::string Ledger() { return ReadText(dir_ / "out" / OutputLedger::kFileName); }
  fs::path dir_;
};

TEST_F(OutputFolder, ARunRemovesWhatTheRunBeforeItWroteAndNeverTheUsers) {
  const fs::path out = dir_ / "out";
  fs::create_directories(out / "lines/mydata");
  std::ofstream(out / "lines/mydata/notes.txt") << "notes";
  std::ofstream(out / "lines/mydata/results.nc") << "the user's own, named like a result";
  Scene("spread_mooring", "duration = 60.0", "spread.toml");
  Scene("catenary", "duration = 2.0", "catenary.toml");

  ASSERT_EQ(Run("run spread.toml --out out --no-film"), 0) << ReadText(dir_ / "err.txt");
  EXPECT_TRUE(fs::exists(out / "lines/leg2/timeseries.csv"));
  EXPECT_NE(Ledger().find("\nlines/leg2/results.nc\n"), std::string::npos) << Ledger();

  ASSERT_EQ(Run("run catenary.toml --out out --frames"), 0) << ReadText(dir_ / "err.txt");
  EXPECT_FALSE(fs::exists(out / "lines/leg2"));  // the system's line folders, gone
  EXPECT_FALSE(fs::exists(out / "points.csv"));
  EXPECT_TRUE(fs::is_directory(out / "lines"));  // the user's folder, and all in it
  EXPECT_EQ(ReadText(out / "lines/mydata/notes.txt"), "notes");
  EXPECT_EQ(ReadText(out / "lines/mydata/results.nc"), "the user's own, named like a result");
  EXPECT_TRUE(fs::exists(out / "film.mp4"));
  EXPECT_TRUE(fs::exists(out / "frames/frame_000000.png"));
  // Written by the modules the program loads (results.nc, the film), listed all the same.
  for (const char* name : {"\nresults.nc\n", "\nfilm.mp4\n", "\nframes/\n",
                           "\nframes/frame_000000.png\n"})
    EXPECT_NE(Ledger().find(name), std::string::npos) << name << " not in\n" << Ledger();

  // A killed run's temporary file of a result, and a user's file in the film's folder.
  std::ofstream(out / "results.nc.tmp999999") << "killed";
  std::ofstream(out / "frames/README") << "the user's";
  ASSERT_EQ(Run("run catenary.toml --out out --no-film"), 0) << ReadText(dir_ / "err.txt");
  EXPECT_FALSE(fs::exists(out / "film.mp4"));
  EXPECT_FALSE(fs::exists(out / "frames/frame_000000.png"));
  EXPECT_FALSE(fs::exists(out / "results.nc.tmp999999"));
  EXPECT_EQ(ReadText(out / "frames/README"), "the user's");  // and its folder with it
  EXPECT_TRUE(fs::exists(out / "results.nc"));
  EXPECT_TRUE(fs::exists(out / "lines/mydata/notes.txt"));
}

}  // namespace
}  // namespace cablefilm
