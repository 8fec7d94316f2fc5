#include "data_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "granpipe/binary_signature.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/text_words.hpp"

namespace granpipe::lammps_data {

namespace {

struct Atom {
  std::int64_t id = 0;
  int type = 0;
  double diameter = 0.0;
  Eigen::Vector3d x;
};

// Far longer than any line of a data file (an atom's is under 200 characters).
constexpr std::size_t kLongestLine = std::size_t{1} << 20;

// The file's lines, numbered from 1 as an editor shows them.
class Lines {
 public:
  Lines(std::istream& in, const std::string& where) : in_(in), where_(where) {}
  bool next(std::string& line) {
    line.clear();
    // A file without line ends (5 GB of zeros) was read whole into one line before it was
    // refused for its missing "N atoms".
    int c = 0;
    while ((c = in_.get()) != EOF && c != '\n') {
      if (line.size() == kLongestLine + 1) {  // + 1: a Windows line end's carriage return
        throw InputError(where_ + ": line " + std::to_string(number_ + 1) +
                         ": expected a line of a LAMMPS data file, got one longer than " +
                         std::to_string(kLongestLine) + " characters");
      }
      line.push_back(static_cast<char>(c));
    }
    if (c == EOF && line.empty()) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // written on Windows
    if (line.size() > kLongestLine) {
      throw InputError(where_ + ": line " + std::to_string(number_ + 1) +
                       ": expected a line of a LAMMPS data file, got one longer than " +
                       std::to_string(kLongestLine) + " characters");
    }
    ++number_;
    return true;
  }
  long number() const { return number_; }

 private:
  std::istream& in_;
  std::string where_;
  long number_ = 0;
};

std::string_view before_comment(std::string_view line) { return line.substr(0, line.find('#')); }

// A section starts with its name ("Atoms", "Velocities", "Masses"): a word, where header
// and data lines start with numbers.
bool is_section(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first != std::string::npos && std::isalpha(static_cast<unsigned char>(line[first]));
}

struct AtomsSection {
  long count = -1;        // from the header
  long count_line = 0;    // the header line giving it
  long section_line = 0;  // the "Atoms" line
  long types = 0;         // from the header's "N atom types"; 0: not given
  long types_line = 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  // the box
  std::array<long, 3> box_line{0, 0, 0};  // of "lo hi xlo xhi" and so on; 0: none yet
};

constexpr std::array<std::array<const char*, 2>, 3> kBoxWords{
    {{"xlo", "xhi"}, {"ylo", "yhi"}, {"zlo", "zhi"}}};

// A header line "lo hi xlo xhi" (or y, z) sets the box along its axis; a triclinic box's
// "xy xz yz" line is refused (granpipe's containers have right angles, as lammps_dump says).
void read_box_line(const std::vector<std::string_view>& w, const std::string& line, long number,
                   const std::string& where, AtomsSection& a) {
  const std::string at = where + ": line " + std::to_string(number);
  if (w.size() == 6 && w[3] == "xy") {
    throw InputError(at + ": expected an orthogonal box, got a triclinic one's tilt " +
                     quoted(line) + ": granpipe's containers have right angles");
  }
  for (int k = 0; k < 3 && w.size() == 4; ++k) {
    if (w[2] != kBoxWords[k][0] || w[3] != kBoxWords[k][1]) continue;
    // Two lines for one axis: the last was taken without a word (a packing fraction of
    // another box).
    if (a.box_line[k] != 0) {
      throw InputError(at + ": expected one \"lo hi " + kBoxWords[k][0] + " " + kBoxWords[k][1] +
                       "\" line, got a second (the first on line " + std::to_string(a.box_line[k]) +
                       ")");
    }
    const auto lo = real_number(w[0]), hi = real_number(w[1]);
    if (!lo || !hi || !std::isfinite(*lo) || !std::isfinite(*hi) || !(*lo < *hi)) {
      throw InputError(at + ": expected \"lo hi " + kBoxWords[k][0] + " " + kBoxWords[k][1] +
                       "\" with finite lo < hi, got " + quoted(line));
    }
    a.lo[k] = *lo;
    a.hi[k] = *hi;
    a.box_line[k] = number;
  }
}

// The box lines are optional to the parser but not to the frame: its x and y sides, where
// no wall is stated, are the box's (an invented box gave a packing fraction of another
// volume, exit 0).
void check_box(const AtomsSection& a, const std::string& where) {
  for (int k = 0; k < 3; ++k) {
    if (a.box_line[k] != 0) continue;
    throw InputError(where + ": expected the header line \"lo hi " + kBoxWords[k][0] + " " +
                     kBoxWords[k][1] + "\" of the box (as write_data writes it), got none");
  }
}

// The header's "N atoms", then on to the Atoms section, whose atom style must be sphere and
// must be said: atom_style full has sphere's seven columns (id mol type q x y z), and read as
// sphere its types would be diameters, so a section that names no style is not guessed at.
AtomsSection find_atoms_section(Lines& lines, const std::string& where) {
  AtomsSection a;
  std::string line;
  lines.next(line);  // the title
  // A dump's first line would pass for a title, and its lines hold no "N atoms".
  if (line.starts_with("ITEM:")) {
    throw InputError(where +
                     ": line 1: expected a LAMMPS data file (a title, then \"N atoms\"), got " +
                     quoted(line) + ": this is a LAMMPS dump, use the lammps_dump source");
  }
  // A binary file was read as text and blamed for a missing "N atoms": name what it is.
  const BinarySignature signature = binary_signature(line);
  const char* binary = signature == BinarySignature::Hdf5   ? "an HDF5 file: use the h5md source"
                       : signature == BinarySignature::Gzip ? "a gzip file: decompress it first"
                                                            : nullptr;
  if (binary) {
    throw InputError(
        where + ": line 1: expected a LAMMPS data file (a title, then \"N atoms\"), got " + binary);
  }
  bool header = true;
  while (lines.next(line)) {
    const std::vector<std::string_view> w = words(before_comment(line));
    header = header && !is_section(line);
    if (header) read_box_line(w, line, lines.number(), where, a);
    if (header && w.size() == 2 && w[1] == "atoms") {
      if (a.count_line != 0) {
        throw InputError(where + ": line " + std::to_string(lines.number()) +
                         ": expected one \"N atoms\" line, got a second (the first on line " +
                         std::to_string(a.count_line) + ")");
      }
      const auto count = whole_number(w[0]);
      a.count = count ? *count : -1;
      if (a.count < 0) {
        throw InputError(where + ": line " + std::to_string(lines.number()) +
                         ": expected \"N atoms\" with N a whole number >= 0, got " + quoted(line));
      }
      a.count_line = lines.number();
    }
    if (header && w.size() == 3 && w[1] == "atom" && w[2] == "types") {
      const auto types = whole_number(w[0]);
      if (!types || *types < 1) {
        throw InputError(where + ": line " + std::to_string(lines.number()) +
                         ": expected \"N atom types\" with N a whole number >= 1, got " +
                         quoted(line));
      }
      a.types = static_cast<long>(*types);
      a.types_line = lines.number();
    }
    if (w.empty() || w[0] != "Atoms") continue;
    a.section_line = lines.number();
    const std::size_t hash = line.find('#');
    const std::vector<std::string_view> style =
        hash == std::string::npos ? std::vector<std::string_view>{}
                                  : words(std::string_view(line).substr(hash + 1));
    const std::string at = where + ": line " + std::to_string(lines.number());
    if (style.empty()) {
      throw InputError(at + ": expected the Atoms section to name its atom style (\"Atoms # " +
                       "sphere\", as write_data writes it), got " + quoted(line) +
                       ": atom_style full has sphere's 7 columns and would be misread");
    }
    if (style[0] != "sphere") {
      throw InputError(at + ": expected the Atoms section of atom_style sphere, got atom_style \"" +
                       std::string(style[0]) + "\"");
    }
    break;
  }
  if (a.count < 0 || a.section_line == 0) {
    throw InputError(where + ": expected a header line \"N atoms\" and an Atoms section, got " +
                     std::string(a.count < 0 ? "no \"N atoms\"" : "no Atoms section"));
  }
  return a;
}

// LAMMPS numbers atoms and types from 1; ids and types are whole numbers, not "1.5" read
// as 1 and a type ".5".
Atom parse_atom(const std::string& line, long number, const std::string& where) {
  const std::vector<std::string_view> w = words(before_comment(line));
  const std::string at = where + ": line " + std::to_string(number);
  if (w.size() != 7 && w.size() != 10) {  // image flags or none
    throw InputError(at +
                     ": expected \"id type diameter density x y z\" (atom_style sphere), got " +
                     quoted(line));
  }
  const auto id = whole_number(w[0]), type = whole_number(w[1]);
  if (!id || *id < 1 || !type || *type < 1 || *type > std::numeric_limits<int>::max()) {
    throw InputError(at + ": expected an atom id and a type, whole numbers >= 1 (up to " +
                     std::to_string(std::numeric_limits<int>::max()) + " types), got " +
                     quoted(line));
  }
  Atom a{*id, static_cast<int>(*type), 0.0, Eigen::Vector3d::Zero()};
  const auto diameter = real_number(w[2]);
  std::array<std::optional<double>, 3> x{real_number(w[4]), real_number(w[5]), real_number(w[6])};
  if (!diameter || !real_number(w[3]) || !x[0] || !x[1] || !x[2]) {
    throw InputError(at +
                     ": expected \"id type diameter density x y z\" (atom_style sphere), got " +
                     quoted(line));
  }
  // LAMMPS refuses a density <= 0 (a mass, for a point particle) and reads image flags as
  // integers: anything else is another format's line.
  const double density = *real_number(w[3]);
  if (!(density > 0.0) || !std::isfinite(density)) {
    throw InputError(at + ": expected a finite density > 0 in column 4, got " + quoted(w[3]));
  }
  for (std::size_t k = 7; k < w.size(); ++k) {
    if (whole_number(w[k])) continue;
    throw InputError(at + ": expected whole-number image flags in columns 8 to 10, got " +
                     quoted(line));
  }
  // An atom that crossed a side shows that side was periodic, which the sides read as open
  // are not: the pairs across it were lost (a packing fraction of 0.458 for 0.485, exit 0).
  for (std::size_t k = 7; k < w.size(); ++k) {
    if (*whole_number(w[k]) == 0) continue;
    throw InputError(at + ": expected image flags 0 (a data file's sides are read as open), " +
                     "got " + std::string(w[k]) + " along " + "xyz"[k - 7] + " in " + quoted(line) +
                     ": the run was periodic along " + "xyz"[k - 7] +
                     "; read its dump with the lammps_dump source, which reads periodic sides");
  }
  // LAMMPS refuses "nan" where it reads a number; named here with its line, not later by
  // the atom's id alone.
  if (!std::isfinite(*diameter) || !std::isfinite(*x[0]) || !std::isfinite(*x[1]) ||
      !std::isfinite(*x[2])) {
    throw InputError(at + ": expected a finite diameter and position, got " + quoted(line));
  }
  a.diameter = *diameter;
  a.x = {*x[0], *x[1], *x[2]};
  return a;
}

// LAMMPS refuses a type beyond the header's count; read, it became a species of its own.
void refuse_undeclared_type(const Atom& atom, const AtomsSection& section, long number,
                            const std::string& where) {
  if (section.types == 0 || atom.type <= section.types) return;
  throw InputError(where + ": line " + std::to_string(number) +
                   ": expected an atom type from 1 to " + std::to_string(section.types) +
                   " (the header's \"atom types\", line " + std::to_string(section.types_line) +
                   "), got " + std::to_string(atom.type));
}

// The Atoms section's lines, up to the next section or the end of the file; each id once.
// `next_section` gets the line that ended it ("" at the end of the file).
std::vector<Atom> read_section(Lines& lines, const AtomsSection& section, const std::string& where,
                               std::string& next_section) {
  std::vector<Atom> out;
  std::map<std::int64_t, long> line_of_id;
  std::string line;
  next_section.clear();
  while (lines.next(line)) {
    if (is_section(line)) {
      next_section = line;
      break;
    }
    if (words(before_comment(line)).empty()) continue;
    out.push_back(parse_atom(line, lines.number(), where));
    refuse_undeclared_type(out.back(), section, lines.number(), where);
    const auto [seen, fresh] = line_of_id.emplace(out.back().id, lines.number());
    if (!fresh) {
      throw InputError(where + ": line " + std::to_string(lines.number()) +
                       ": expected each atom id once, got id " + std::to_string(out.back().id) +
                       " again (first on line " + std::to_string(seen->second) + ")");
    }
  }
  return out;
}

// LAMMPS reads one Atoms section: the atoms of a second one (two files joined) were left
// out without a word.
void refuse_second_atoms_section(Lines& lines, std::string line, const AtomsSection& first,
                                 const std::string& where) {
  do {
    const std::vector<std::string_view> w = words(before_comment(line));
    if (w.empty() || w[0] != "Atoms") continue;
    throw InputError(where + ": line " + std::to_string(lines.number()) +
                     ": expected one Atoms section, got a second (the first on line " +
                     std::to_string(first.section_line) + ")");
  } while (lines.next(line));
}

void check_count(const std::vector<Atom>& atoms, const AtomsSection& section,
                 const std::string& where) {
  if (static_cast<long>(atoms.size()) == section.count) return;
  throw InputError(where + ": line " + std::to_string(section.section_line) +
                   ": expected the Atoms section to hold " + std::to_string(section.count) +
                   " atoms (the header's, line " + std::to_string(section.count_line) + "), got " +
                   std::to_string(atoms.size()));
}

}  // namespace

Frame read_atoms(std::istream& in, const std::string& where) {
  Lines lines(in, where);
  const AtomsSection section = find_atoms_section(lines, where);
  std::string next_section;
  std::vector<Atom> list = read_section(lines, section, where, next_section);
  if (!next_section.empty()) refuse_second_atoms_section(lines, next_section, section, where);
  check_count(list, section, where);
  check_box(section, where);
  std::sort(list.begin(), list.end(), [](const Atom& a, const Atom& b) { return a.id < b.id; });
  Frame f;
  f.resize(static_cast<Eigen::Index>(list.size()), 3);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    f.position().row(i) = list[k].x.transpose().array();
    f.radius()[i] = 0.5 * list[k].diameter;
    f.id()[i] = list[k].id;
    f.species()[i] = list[k].type - 1;
  }
  // A data file says nothing of walls or periodic sides (the input script does): open sides.
  f.container.lo = section.lo;
  f.container.hi = section.hi;
  for (auto& sides : f.container.boundary) sides = {Boundary::Open, Boundary::Open};
  return f;
}

}  // namespace granpipe::lammps_data
