#pragma once
// What a file given as a dump is when it is not one, for the refusal: another LAMMPS file
// or an H5MD file is named with the source that reads it.
#include <string>

#include "text_lines.hpp"

namespace granpipe::lammps_dump {

// `first_line`, the file's first line that is not blank, was the line last read and does
// not start with "ITEM:". Reads on to recognise a data file's header. E.g. "a LAMMPS data
// file (\"2 atoms\" on line 3): use the lammps_data source".
std::string what_the_file_is(TextLines& lines, const std::string& first_line);

}  // namespace granpipe::lammps_dump
