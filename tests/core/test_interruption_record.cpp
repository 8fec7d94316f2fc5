// A signal asks a run to stop once: the same signal sent again at once is the same request,
// one sent again later ends the run at once (interruption_record.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "interruption_record.hpp"
#include "run_marker.hpp"
#include "test_files.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

// A run's folder with a marker the handler may overwrite.
fs::path run_folder(const std::string& name) {
  const fs::path dir = test::fresh_path("interruption", name);
  fs::create_directories(dir);
  std::ofstream(dir / kRunMarkerName) << std::string(kRunMarkerSize, ' ');
  return dir;
}

int stop_requested() {
  try {
    throw_if_stop_requested();
  } catch (const StopRequested& stop) {
    return stop.signal;
  }
  return 0;
}

}  // namespace

// timeout(1) sends SIGTERM to the run and then to its process group: as a second signal it
// ended the run at once, its frames.partial.h5 left open for writing (h5py could not open
// it).
TEST(InterruptionRecord, ASignalSentTwiceAtOnceIsOneRequest) {
  const fs::path dir = run_folder("twice");
  {
    const InterruptionRecord record(dir, std::string(kRunMarkerSize, ' '), "test");
    std::raise(SIGTERM);
    std::raise(SIGTERM);  // ended this program before
    EXPECT_EQ(stop_requested(), SIGTERM);
  }
  EXPECT_EQ(test::read_file(dir / "run.log"), "interrupted by SIGTERM before the run finished\n");
  fs::remove_all(dir);
}

TEST(InterruptionRecordDeathTest, ASignalSentAgainLaterEndsTheRunAtOnce) {
  const fs::path dir = run_folder("later");
  EXPECT_EXIT(
      {
        const InterruptionRecord record(dir, std::string(kRunMarkerSize, ' '), "test");
        std::raise(SIGTERM);
        std::this_thread::sleep_for(std::chrono::milliseconds(700));
        std::raise(SIGTERM);
        std::_Exit(0);
      },
      testing::KilledBySignal(SIGTERM), "");
  fs::remove_all(dir);
}
