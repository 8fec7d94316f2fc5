#include "lammps_data_source.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

namespace granpipe::lammps_data {

namespace {

struct Atom {
  std::int64_t id = 0;
  int type = 0;
  double diameter = 0.0;
  Eigen::Vector3d x;
};

// Reads "N atoms" from the header and the Atoms section's N lines.
std::vector<Atom> atoms(std::istream& in, const std::string& where) {
  std::string line;
  long count = -1, number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream s(line);
    long n = 0;
    std::string word;
    if (count < 0 && (s >> n >> word) && word == "atoms") count = n;
    if (line.rfind("Atoms", 0) == 0) break;
  }
  if (count < 0 || in.eof()) throw InputError(where + ": expected a header \"N atoms\" and an Atoms section");
  std::vector<Atom> out;
  while (static_cast<long>(out.size()) < count && std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream s(line);
    Atom a;
    double density = 0.0;
    if (!(s >> a.id >> a.type >> a.diameter >> density >> a.x[0] >> a.x[1] >> a.x[2]) || a.type < 1) {
      throw InputError(where + ": line " + std::to_string(number) +
                       ": expected \"id type diameter density x y z\" (atom_style sphere), got \"" +
                       line.substr(0, 60) + "\"");
    }
    out.push_back(a);
  }
  if (static_cast<long>(out.size()) != count) {
    throw InputError(where + ": expected " + std::to_string(count) + " atoms, got " +
                     std::to_string(out.size()));
  }
  std::sort(out.begin(), out.end(), [](const Atom& a, const Atom& b) { return a.id < b.id; });
  return out;
}

}  // namespace

Frame read_atoms(std::istream& in, const std::string& where) {
  const std::vector<Atom> list = atoms(in, where);
  Frame f;
  f.resize(static_cast<Eigen::Index>(list.size()), 3);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    f.position().row(i) = list[k].x.transpose().array();
    f.radius()[i] = 0.5 * list[k].diameter;
    f.id()[i] = list[k].id;
    f.species()[i] = list[k].type - 1;
  }
  return f;
}

Schema schema() {
  Schema s;
  s.path("file", std::nullopt, "LAMMPS data file (atom_style sphere)");
  s.real("cylinder_radius", 0.0, "radius of the vertical cylinder the particles are in (0: none)")
      .min(0.0).unit("length");
  s.real("base", 0.0, "height of the flat base").unit("length");
  s.real("top", 100.0, "height of the container's open top").unit("length");
  return s;
}

LammpsDataSource::LammpsDataSource(const PluginContext& ctx) {
  const std::string file = ctx.params.string("file");
  std::ifstream in(file);
  if (!in) throw InputError(ctx.param("file") + ": cannot read " + file);
  frame_ = read_atoms(in, file);
  const double r = ctx.params.real("cylinder_radius"), base = ctx.params.real("base");
  const double top = ctx.params.real("top");
  if (!(top > base)) throw InputError(ctx.param("top") + ": expected a height above base, got " + std::to_string(top));
  const double half = r > 0 ? r : (frame_.position().leftCols(2).abs().maxCoeff() + frame_.radius().maxCoeff());
  frame_.container = Container::open_top_box(3, Eigen::Vector3d(-half, -half, base),
                                             Eigen::Vector3d(half, half, top));
  if (r > 0) {
    frame_.container.shape = ContainerShape::Cylinder;
    frame_.container.cylinder_radius = r;
  }
}

bool LammpsDataSource::next(Frame& frame) {
  if (done_) return false;
  frame = frame_;
  done_ = true;
  return true;
}

}  // namespace granpipe::lammps_data
