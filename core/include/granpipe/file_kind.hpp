#pragma once
// What stands at a path where a file was expected, in words for a one-line message, without
// throwing: std::filesystem's throwing queries turned a loop of symbolic links into an
// internal error (exit 1), and its non-throwing ones called it "no such file".
#include <filesystem>
#include <string>

namespace granpipe {

// "a regular file", "no such file", "a directory", "a loop of symbolic links", "a symbolic
// link to nothing (its target)", "no regular file (a pipe, socket or device)" or "a path
// that cannot be searched (permissions)". Symbolic links are followed.
std::string what_is_at(const std::filesystem::path& path);

// Whether a regular file is there, symbolic links followed.
bool regular_file_at(const std::filesystem::path& path);

// Whether anything is there (a dangling or looping link counts: it is something to report).
bool anything_at(const std::filesystem::path& path);

}  // namespace granpipe
