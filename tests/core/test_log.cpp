// The run's log holds every line: those written before it opens (the plugins' checks run
// before the output directory exists) and, with quiet, those kept off the terminal.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "granpipe/log.hpp"
#include "test_files.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

using test::read_file;

fs::path fresh(const std::string& name) { return test::fresh_path("log", name); }

}  // namespace

TEST(Log, AWarningBeforeTheLogOpensReachesItEvenWhenQuiet) {
  const fs::path path = fresh("early");
  Log log;
  log.set_quiet(true);
  log.warn("dt is t_c/12");
  log.open_file(path.string());
  log.info("started");
  EXPECT_EQ(read_file(path), "warning: dt is t_c/12\nstarted\n");
  fs::remove(path);
}

// The run's provenance line is its log's first, before the plugins' early warnings.
TEST(Log, TheFirstLineGoesBeforeTheLinesKept) {
  const fs::path path = fresh("provenance");
  Log log;
  log.set_quiet(true);
  log.warn("positions printed to 6 digits");
  log.open_file(path.string(), "granpipe 0.1.0 (abc): run, seed 1");
  log.info("done");
  EXPECT_EQ(read_file(path),
            "granpipe 0.1.0 (abc): run, seed 1\nwarning: positions printed to 6 digits\ndone\n");
  fs::remove(path);
}

TEST(Log, AClosedLogKeepsTheNextRunsLinesForTheNextLog) {
  const fs::path first = fresh("first"), second = fresh("second");
  Log log;
  log.set_quiet(true);
  log.open_file(first.string());
  log.info("run 1");
  log.close_file();
  log.warn("checked before run 2");
  log.open_file(second.string());
  EXPECT_EQ(read_file(first), "run 1\n");
  EXPECT_EQ(read_file(second), "warning: checked before run 2\n");
  fs::remove(first);
  fs::remove(second);
}
