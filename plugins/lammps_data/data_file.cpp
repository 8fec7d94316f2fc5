#include "data_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <sstream>
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

// The file's lines, numbered from 1 as an editor shows them.
class Lines {
 public:
  explicit Lines(std::istream& in) : in_(in) {}
  bool next(std::string& line) {
    if (!std::getline(in_, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // written on Windows
    ++number_;
    return true;
  }
  long number() const { return number_; }

 private:
  std::istream& in_;
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
      const auto count = whole_number(w[0]);
      a.count = count ? *count : -1;
      if (a.count < 0) {
        throw InputError(where + ": line " + std::to_string(lines.number()) +
                         ": expected \"N atoms\" with N a whole number >= 0, got " + quoted(line));
      }
      a.count_line = lines.number();
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

Atom parse_atom(const std::string& line, long number, const std::string& where) {
  const std::vector<std::string_view> w = words(before_comment(line));
  std::istringstream s{std::string(before_comment(line))};
  Atom a;
  double density = 0.0;
  const bool columns = w.size() == 7 || w.size() == 10;  // image flags or none
  if (!columns || !(s >> a.id >> a.type >> a.diameter >> density >> a.x[0] >> a.x[1] >> a.x[2]) ||
      a.type < 1) {
    throw InputError(where + ": line " + std::to_string(number) +
                     ": expected \"id type diameter density x y z\" (atom_style sphere), got " +
                     quoted(line));
  }
  return a;
}

// The Atoms section's lines, up to the next section or the end of the file; each id once.
std::vector<Atom> read_section(Lines& lines, const std::string& where) {
  std::vector<Atom> out;
  std::map<std::int64_t, long> line_of_id;
  std::string line;
  while (lines.next(line) && !is_section(line)) {
    if (words(before_comment(line)).empty()) continue;
    out.push_back(parse_atom(line, lines.number(), where));
    const auto [seen, fresh] = line_of_id.emplace(out.back().id, lines.number());
    if (!fresh) {
      throw InputError(where + ": line " + std::to_string(lines.number()) +
                       ": expected each atom id once, got id " + std::to_string(out.back().id) +
                       " again (first on line " + std::to_string(seen->second) + ")");
    }
  }
  return out;
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
  Lines lines(in);
  const AtomsSection section = find_atoms_section(lines, where);
  std::vector<Atom> list = read_section(lines, where);
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
