#include "not_a_dump.hpp"

#include "granpipe/binary_signature.hpp"
#include "granpipe/text_words.hpp"

namespace granpipe::lammps_dump {

namespace {

// A data file's header ends within a few dozen lines of its title, at the first section.
constexpr long kHeaderLines = 50;

bool is_atoms_line(std::string_view line) {
  const auto w = words(line.substr(0, line.find('#')));
  return w.size() == 2 && w[1] == "atoms" && whole_number(w[0]);
}

}  // namespace

std::string what_the_file_is(TextLines& lines, const std::string& first_line) {
  if (binary_signature(first_line) == BinarySignature::Hdf5) {
    return "an HDF5 file: use the h5md source for H5MD frames";
  }
  std::string line = first_line;
  do {
    if (is_atoms_line(line)) {
      return "a LAMMPS data file (" + quoted(trimmed(line)) + " on line " +
             std::to_string(lines.number()) + "): use the lammps_data source";
    }
  } while (lines.number() < kHeaderLines && lines.next(line));
  return quoted(trimmed(first_line));
}

}  // namespace granpipe::lammps_dump
