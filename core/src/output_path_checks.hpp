#pragma once
// What granpipe refuses to use as an output directory, whatever it holds.
#include <filesystem>
#include <string>
#include <vector>

namespace granpipe {

struct InputFile;

// "out/x/" and "out/x//" are "out/x": a trailing separator would make every check below
// see the target of a symlink instead of the symlink.
std::filesystem::path without_trailing_separators(const std::filesystem::path& dir);

// Throws InputError when "." or ".." follow a named folder in `dir` (leading ones, as in
// ../results, are the working directory's): out/x/. is out/x under another name, and
// out/missing/../x is refused by the system only once out/missing has been made.
void check_output_spelling(const std::filesystem::path& dir);

// Throws InputError unless `dir` is a directory or does not exist yet: a symlink (to
// anything), a regular file or a special file is refused.
void check_output_kind(const std::filesystem::path& dir);

// Throws InputError when `dir` is or holds the root, the working or the home directory,
// or one of `inputs`: granpipe never writes where it reads or where a user lives.
void check_output_place(const std::filesystem::path& dir, const std::vector<InputFile>& inputs);

// Throws InputError naming the first folder in `dir` whose entries this process may not
// remove, so that --overwrite is refused before anything changes.
void check_removable(const std::filesystem::path& dir);

}  // namespace granpipe
