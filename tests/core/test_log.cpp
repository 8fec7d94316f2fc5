// The run's log holds every line: those written before it opens (the plugins' checks run
// before the output directory exists) and, with quiet, those kept off the terminal.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "granpipe/log.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".log");
  fs::remove(p);
  return p;
}

}  // namespace

TEST(Log, AWarningBeforeTheLogOpensReachesItEvenWhenQuiet) {
  const fs::path path = fresh("granpipe_log_early");
  Log log;
  log.set_quiet(true);
  log.warn("dt is t_c/12");
  log.open_file(path.string());
  log.info("started");
  EXPECT_EQ(read(path), "warning: dt is t_c/12\nstarted\n");
  fs::remove(path);
}

// The run's provenance line is its log's first, before the plugins' early warnings.
TEST(Log, TheFirstLineGoesBeforeTheLinesKept) {
  const fs::path path = fresh("granpipe_log_provenance");
  Log log;
  log.set_quiet(true);
  log.warn("positions printed to 6 digits");
  log.open_file(path.string(), "granpipe 0.1.0 (abc): run, seed 1");
  log.info("done");
  EXPECT_EQ(read(path),
            "granpipe 0.1.0 (abc): run, seed 1\nwarning: positions printed to 6 digits\ndone\n");
  fs::remove(path);
}

TEST(Log, AClosedLogKeepsTheNextRunsLinesForTheNextLog) {
  const fs::path first = fresh("granpipe_log_first"), second = fresh("granpipe_log_second");
  Log log;
  log.set_quiet(true);
  log.open_file(first.string());
  log.info("run 1");
  log.close_file();
  log.warn("checked before run 2");
  log.open_file(second.string());
  EXPECT_EQ(read(first), "run 1\n");
  EXPECT_EQ(read(second), "warning: checked before run 2\n");
  fs::remove(first);
  fs::remove(second);
}
