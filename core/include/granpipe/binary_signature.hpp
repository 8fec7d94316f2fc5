#pragma once
// The text readers (LAMMPS data files and dumps) are given binary files by mistake: an H5MD
// file, a gzip-compressed data file. Read as text, such a file was blamed for a missing header
// line; its signature names it instead. The signatures live here, each reader gives its own
// advice (the dump reader reads gzip itself).
#include <string_view>

namespace granpipe {

enum class BinarySignature { None, Hdf5, Gzip };

// The kind whose signature `first_bytes` starts with (a file's first line read as text holds
// it: HDF5's "\x89HDF\r\n\x1a\n" ends at its '\n', gzip's two bytes come first).
inline BinarySignature binary_signature(std::string_view first_bytes) {
  if (first_bytes.starts_with("\x89HDF")) return BinarySignature::Hdf5;
  if (first_bytes.starts_with("\x1f\x8b")) return BinarySignature::Gzip;
  return BinarySignature::None;
}

}  // namespace granpipe
