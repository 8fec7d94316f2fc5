// A file written whole or not at all (granpipe/atomic_file.hpp): the temporary it is written
// under never outlives a failure.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "granpipe/atomic_file.hpp"
#include "granpipe/errors.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = granpipe::test::fresh_path("atomic", name);
  fs::create_directories(d);
  return d;
}

using granpipe::test::read_file;

}  // namespace

TEST(AtomicFile, ReplacesTheFileWhole) {
  const fs::path dir = fresh_dir("replace");
  granpipe::write_file_atomically(dir / "a.txt", "first");
  granpipe::write_file_atomically(dir / "a.txt", "second");
  EXPECT_EQ(read_file(dir / "a.txt"), "second");
  EXPECT_FALSE(fs::exists(dir / "a.txt.tmp"));
  fs::remove_all(dir);
}

// A rename that fails (a folder where the file goes) left its temporary behind, which the
// run had not listed, and a later --overwrite refused the folder for it.
TEST(AtomicFile, AFailedRenameLeavesNoTemporary) {
  const fs::path dir = fresh_dir("rename");
  fs::create_directory(dir / "b.pvd");
  fs::create_directory(dir / "b.pvd" / "inside");
  EXPECT_THROW(granpipe::write_file_atomically(dir / "b.pvd", "text"), granpipe::InputError);
  EXPECT_FALSE(fs::exists(dir / "b.pvd.tmp"));
  EXPECT_TRUE(fs::is_directory(dir / "b.pvd" / "inside"));
  fs::remove_all(dir);
}

// A symlink planted at the temporary name while a run went had the run's file written over
// what it pointed to, outside the run's folder (exit 0): refused, the link and its target
// left as they were.
TEST(AtomicFile, ASymlinkAtTheTemporaryNameIsNotWrittenThrough) {
  const fs::path dir = fresh_dir("symlink");
  granpipe::write_file_atomically(dir / "user.txt", "the user's");
  fs::create_symlink(dir / "user.txt", dir / "a.txt.tmp");
  try {
    granpipe::write_file_atomically(dir / "a.txt", "the run's");
    FAIL() << "expected an InputError";
  } catch (const granpipe::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "a.txt.tmp").string() +
                  ": expected no file at this temporary name, got one (not granpipe's now: left "
                  "as it is)");
  }
  EXPECT_EQ(read_file(dir / "user.txt"), "the user's");
  EXPECT_TRUE(fs::is_symlink(dir / "a.txt.tmp"));
  EXPECT_FALSE(fs::exists(dir / "a.txt"));
  fs::remove_all(dir);
}
