#pragma once
// What follows the last gzip member of a file. zlib's gzread stops silently at bytes after
// a member that do not start another one, so text appended to a compressed dump (or a
// second file joined to it) would be left out without a word.
#include <cstdint>
#include <optional>
#include <string>

namespace granpipe::lammps_dump {

// The offset in the file of the first byte after its gzip members that starts no member,
// or nothing when the members run to the end of the file. `text_bytes` and `text_crc` are
// the length and CRC-32 of the decompressed text, read whole: when the last member's
// trailer holds both, the file is one member and no second pass is needed. InputError
// naming `path` when the file cannot be read again.
std::optional<std::int64_t> bytes_after_gzip(const std::string& path, std::int64_t text_bytes,
                                             std::uint32_t text_crc);

}  // namespace granpipe::lammps_dump
