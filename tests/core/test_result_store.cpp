// The results files a run writes at its end (granpipe/result_store.hpp): written under
// temporary names that are never written through.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "granpipe/errors.hpp"
#include "granpipe/output_files.hpp"
#include "granpipe/result_store.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;
using namespace granpipe;

namespace {

ResultSet one_scalar() {
  Results r;
  r.add_scalar("x", 1.5);
  return {{"meanx", r}};
}

}  // namespace

// Symlinks planted at results.h5.tmp or a CSV's .tmp while a run went had the results
// written over the files they pointed to, outside the run's folder (exit 0).
TEST(ResultStore, SymlinksAtTheTemporaryNamesAreNotWrittenThrough) {
  for (const char* planted : {"results.h5.tmp", "meanx.scalars.csv.tmp"}) {
    const fs::path dir = test::fresh_path("result_store", planted);
    fs::create_directories(dir);
    const fs::path user = dir / "user.txt";
    { std::ofstream(user) << "the user's"; }
    fs::create_symlink(user, dir / planted);
    FileRecord record;
    try {
      write_results(dir, one_scalar(), Provenance{}, record);
      FAIL() << "expected an InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("expected no file at this temporary name"),
                std::string::npos)
          << e.what();
    }
    EXPECT_EQ(test::read_file(user), "the user's") << planted;
    EXPECT_TRUE(fs::is_symlink(dir / planted)) << planted;
    EXPECT_FALSE(fs::exists(dir / "results.h5")) << planted;
    EXPECT_FALSE(fs::exists(dir / "results.h5.tmp") && !fs::is_symlink(dir / "results.h5.tmp"));
    fs::remove_all(dir);
  }
}
