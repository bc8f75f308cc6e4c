// The output folder's ledger: a run removes what the run before it wrote there, and nothing
// else, whatever the names, links or ledger it finds.
#include <gtest/gtest.h>
#include <sys/file.h>
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "io/atomic_file.h"
#include "io/out_dir_lock.h"
#include "io/output_ledger.h"

namespace cablefilm {
namespace {

namespace fs = std::filesystem;

class OutputLedgerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("cablefilm_ledger_test_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    out_ = root_ / "out";
    fs::create_directories(out_);
  }
  void TearDown() override { fs::remove_all(root_); }
  static void Put(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
  }
  static void Write(const fs::path& p, const std::string& text) {  // as a run writes its files
    AtomicFile file(p.string());
    std::fputs(text.c_str(), file.stream());
    file.Commit();
  }
  static std::string Read(const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  fs::path root_, out_;
};

TEST_F(OutputLedgerTest, TheNextRunRemovesWhatTheLastWroteAndNothingElse) {
  // The user's own files, one of them named as a run names a line's results.
  Put(out_ / "lines/mydata/notes.txt", "notes");
  Put(out_ / "lines/mydata/results.nc", "mine");
  Put(out_ / "timeseries.csv", "the user's, before any run");
  {
    OutDirLock lock;
    lock.Lock(out_.string(), "output folder");
    CreateOutputFolder((out_ / "lines/leg1").string());
    Write(out_ / "lines/leg1/timeseries.csv", "run 1");
    Write(out_ / "timeseries.csv", "run 1");  // over the user's file: now the run's
  }
  EXPECT_EQ(Read(out_ / "lines/leg1/timeseries.csv"), "run 1");
  {
    OutDirLock lock;
    lock.Lock(out_.string(), "output folder");
    EXPECT_FALSE(fs::exists(out_ / "lines/leg1"));  // made by the run: emptied, then removed
    EXPECT_FALSE(fs::exists(out_ / "timeseries.csv"));
    EXPECT_EQ(Read(out_ / "lines/mydata/notes.txt"), "notes");
    EXPECT_EQ(Read(out_ / "lines/mydata/results.nc"), "mine");
  }
}

TEST_F(OutputLedgerTest, AFolderThatWasThereStaysWhenEmptied) {
  fs::create_directories(out_ / "lines");
  {
    OutDirLock lock;
    lock.Lock(out_.string(), "output folder");
    CreateOutputFolder((out_ / "lines/leg1/deeper").string());
    Write(out_ / "lines/leg1/deeper/a.csv", "run");
  }
  OutDirLock lock;
  lock.Lock(out_.string(), "output folder");
  EXPECT_TRUE(fs::is_directory(out_ / "lines"));  // the user's
  EXPECT_FALSE(fs::exists(out_ / "lines/leg1"));  // the run's, both levels
}

TEST_F(OutputLedgerTest, TemporariesOfAKilledRunGoTheUsersStay) {
  {
    OutDirLock lock;
    lock.Lock(out_.string(), "output folder");
    RecordOutput((out_ / "results.nc").string());  // as a writer does before its temporary
    RecordOutput((out_ / "points.csv").string());
  }
  // What SIGKILL leaves: the temporaries under their process ids; beside them the user's.
  Put(out_ / "results.nc.tmp4242", "killed");
  Put(out_ / "points.csv.tmp17", "killed");
  Put(out_ / "points.csv.tmpx", "the user's");
  Put(out_ / "notes.txt.tmp5", "the user's");
  OutDirLock lock;
  lock.Lock(out_.string(), "output folder");
  EXPECT_FALSE(fs::exists(out_ / "results.nc.tmp4242"));
  EXPECT_FALSE(fs::exists(out_ / "points.csv.tmp17"));
  EXPECT_TRUE(fs::exists(out_ / "points.csv.tmpx"));
  EXPECT_TRUE(fs::exists(out_ / "notes.txt.tmp5"));
}

TEST_F(OutputLedgerTest, AHostileLedgerReachesNothingOutsideTheFolder) {
  Put(root_ / "outside/keep.txt", "keep");
  Put(out_ / "sub/x", "keep");
  fs::create_symlink(root_ / "outside", out_ / "link");
  fs::create_symlink(root_ / "outside/keep.txt", out_ / "named_like_a_result.csv");
  Put(out_ / OutputLedger::kFileName,
      "../outside/keep.txt\n" + (root_ / "outside/keep.txt").string() + "\n" +
          "sub/../../outside/keep.txt\nlink/keep.txt\nlink/\nnamed_like_a_result.csv\n"
          "./sub/x\nsub//x\n\n../outside/\n");
  OutDirLock lock;
  lock.Lock(out_.string(), "output folder");
  EXPECT_EQ(Read(root_ / "outside/keep.txt"), "keep");
  EXPECT_EQ(Read(out_ / "sub/x"), "keep");
  EXPECT_TRUE(fs::is_symlink(out_ / "link"));  // a link is never the run's
  EXPECT_TRUE(fs::is_symlink(out_ / "named_like_a_result.csv"));
}

TEST_F(OutputLedgerTest, ASweepsCaseFolderGoesWithWhatItsRunWrote) {
  {
    OutDirLock sweep;
    sweep.Lock(out_.string(), "sweep folder");
    CreateOutputFolder((out_ / "case_0").string());
    Write(out_ / "case_0/scene.toml", "case");
  }
  {
    OutDirLock run;  // the case's own run, in its folder
    run.Lock((out_ / "case_0").string(), "output folder");
    Write(out_ / "case_0/timeseries.csv", "rows");
  }
  // A run of the case killed: its lock file stays, held by no one.
  Put(out_ / "case_0" / OutDirLock::kFileName, "12345\n");
  OutDirLock sweep;
  sweep.Lock(out_.string(), "sweep folder");
  EXPECT_FALSE(fs::exists(out_ / "case_0"));
}

TEST_F(OutputLedgerTest, ALockAnotherRunHoldsIsLeftAndSoIsItsFolder) {
  {
    OutDirLock sweep;
    sweep.Lock(out_.string(), "sweep folder");
    CreateOutputFolder((out_ / "case_0").string());
  }
  const fs::path held = out_ / "case_0" / OutDirLock::kFileName;
  const int fd = ::open(held.c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // as another process's run would
  {
    OutDirLock sweep;
    sweep.Lock(out_.string(), "sweep folder");
    EXPECT_TRUE(fs::exists(held));
  }
  ::close(fd);
}

TEST_F(OutputLedgerTest, NothingIsRecordedOutsideAnOpenLedgersFolder) {
  {
    OutDirLock lock;
    lock.Lock(out_.string(), "output folder");
    Write(root_ / "elsewhere.csv", "not the run's folder");
    Write(out_ / "mine.csv", "the run's");
  }
  const std::string ledger = Read(out_ / OutputLedger::kFileName);
  EXPECT_NE(ledger.find("\nmine.csv\n"), std::string::npos) << ledger;
  EXPECT_EQ(ledger.find("elsewhere"), std::string::npos) << ledger;
  OutDirLock lock;
  lock.Lock(out_.string(), "output folder");
  EXPECT_TRUE(fs::exists(root_ / "elsewhere.csv"));
  EXPECT_FALSE(fs::exists(out_ / "mine.csv"));
}

}  // namespace
}  // namespace cablefilm
