#pragma once
// Files for tests: a path of the test program's own under the system's temporary folder,
// and a file's whole content.
#include <filesystem>
#include <string>

namespace granpipe::test {

// temp/granpipe_test_<suite>_<name>_<pid>, with whatever an earlier run left there removed
// (the process id keeps two test programs run at once apart). Not created.
std::filesystem::path fresh_path(const std::string& suite, const std::string& name);

// The file's bytes; empty when it cannot be read.
std::string read_file(const std::filesystem::path& file);

}  // namespace granpipe::test
