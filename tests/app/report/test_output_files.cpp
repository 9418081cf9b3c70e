// Output folders and result writes (app/report/output_files.hpp), and the run's
// exit code policy.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "app/report/output_files.hpp"
#include "app/report/run_summary.hpp"
#include "app/report/summary_text.hpp"
#include "tests/support/temp_path.hpp"

namespace fs = std::filesystem;
using namespace handover::app;

TEST(SafeFileName, NamesCannotLeaveTheOutputFolder) {
  EXPECT_EQ(safeFileName("h2r_basic-2.v1"), "h2r_basic-2.v1");
  EXPECT_EQ(safeFileName("../../escaped_by_name"), "_._.._escaped_by_name");
  EXPECT_EQ(safeFileName(".."), "_.");
  EXPECT_EQ(safeFileName(".hidden"), "_hidden");
  EXPECT_EQ(safeFileName("a/b\\c d\xff"), "a_b_c_d_");
  EXPECT_EQ(safeFileName(std::string("a\0b", 3)), "a_b");
  EXPECT_EQ(safeFileName(""), "unnamed");
  EXPECT_EQ(safeFileName(std::string(300, 'x')).size(), kMaxSafeNameBytes);
}

TEST(WriteFileChecked, AFailedWriteIsAnErrorNotAnEmptyFile) {
  // a file size limit fails writes past 1000 bytes with EFBIG, as a full disk
  // fails them with ENOSPC (SIGXFSZ ignored so the write returns the error)
  const std::string path = handover::test::uniqueTempPath("limited.json");
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  getrlimit(RLIMIT_FSIZE, &old);
  rlimit small = old;
  small.rlim_cur = 1000;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  bool threw = false;
  std::string message;
  try {
    writeFileChecked(path, std::string(100000, 'x'));
  } catch (const OutputError& e) {
    threw = true;
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  EXPECT_TRUE(threw);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(path));  // no partial file left behind
  writeFileChecked(path, "abc\n");
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "abc");
}

TEST(PrepareOutputDir, UnwritableFoldersFailBeforeTheRun) {
  // a folder below a regular file cannot exist
  const std::string file = handover::test::uniqueTempPath("a_file");
  std::ofstream(file) << "x";
  EXPECT_THROW(prepareOutputDir(file + "/out"), OutputError);
  EXPECT_THROW(prepareOutputDir(file), OutputError);
  const std::string dir = handover::test::uniqueTempPath("out_ok/sub");
  EXPECT_NO_THROW(prepareOutputDir(dir));
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));  // the probe is removed
}

TEST(CheckVideoPath, MissingFoldersAreNotCreated) {
  const fs::path dir = fs::path(handover::test::uniqueTempPath("no_such_video_dir"));
  fs::remove_all(dir);
  EXPECT_THROW(checkVideoPath((dir / "a.mp4").string()), OutputError);
  EXPECT_FALSE(fs::exists(dir));
  EXPECT_NO_THROW(checkVideoPath(handover::test::uniqueTempPath("a.mp4")));
}

TEST(RunExitCode, UnsafeFailsUnlessExpected) {
  RunSummary r;
  r.outcome = "success";
  EXPECT_EQ(runExitCode(r, false), 0);
  r.outcome = "unsafe";
  EXPECT_EQ(runExitCode(r, false), 1);
  EXPECT_EQ(runExitCode(r, true), 0);  // `expect: outcome: unsafe` held
  r.expectation_failures.push_back("outcome: expected success, got unsafe");
  EXPECT_EQ(runExitCode(r, true), 1);
  r.outcome = "error";
  EXPECT_EQ(runExitCode(r, true), 2);
}

// issue 16: a run that could not see the person fails a script like an unsafe one
TEST(RunExitCode, NoPerceptionFailsUnlessExpected) {
  RunSummary r;
  r.outcome = "no_perception";
  EXPECT_EQ(runExitCode(r, false), 1);
  EXPECT_EQ(runExitCode(r, true), 0);  // `expect: outcome: no_perception` held
}

TEST(RunSummaryJson, CarriesTheTrackerAndItsRejectedSamples) {
  RunSummary r;
  r.outcome = "success";
  r.tracker = "udp";
  r.rejected_samples = 7;
  const std::string j = r.toJson();
  EXPECT_NE(j.find("\"tracker\": {"), std::string::npos) << j;
  EXPECT_NE(j.find("\"source\": \"udp\""), std::string::npos) << j;
  EXPECT_NE(j.find("\"rejected_samples\": 7"), std::string::npos) << j;
}

TEST(RunSummaryJson, CarriesTheRejectedSamplesPerReasonAndTheUnseenTime) {
  RunSummary r;
  r.outcome = "no_perception";
  r.rejected_samples = 5;
  r.rejected_by_reason = {{"workspace", 3}, {"jump", 2}};
  r.person_unseen_time = 4.5;
  const std::string j = r.toJson();
  EXPECT_NE(j.find("\"rejected\": {"), std::string::npos) << j;
  EXPECT_NE(j.find("\"workspace\": 3"), std::string::npos) << j;
  EXPECT_NE(j.find("\"jump\": 2"), std::string::npos) << j;
  EXPECT_NE(j.find("\"unseen_time\": 4.5"), std::string::npos) << j;
  const std::string screen = formatSummary(r);
  EXPECT_NE(screen.find("5 samples rejected (workspace 3, jump 2); person unseen 4.50 s"), std::string::npos) << screen;
}
