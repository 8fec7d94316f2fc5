// Writes the frames.h5 files that tests/h5md_layout_check.py inspects with h5py:
//   full3d.h5  3 frames of 5 spheres with every optional array (velocities, angular
//              velocities, contacts, supports) in a cylinder,
//   bare2d.h5  2 frames of 4 disks with no optional array in a periodic box.
// Values are simple formulas (position = frame + 0.01 particle + 0.001 axis) so that the
// checker can tell a transposed or shifted array from the right one.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "granpipe/errors.hpp"
#include "granpipe/frame_store.hpp"

namespace fs = std::filesystem;
using namespace granpipe;

namespace {

Frame sample(long k, int dim, Eigen::Index n, bool optional_arrays) {
  Frame f;
  f.resize(n, dim);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int a = 0; a < dim; ++a) {
      f.position()(i, a) = static_cast<double>(k) + 0.01 * static_cast<double>(i) + 0.001 * a;
    }
    f.radius()[i] = 0.5 + 0.01 * static_cast<double>(i);
    f.species()[i] = static_cast<std::int32_t>(i % 2);
  }
  f.step = 10 * k;
  f.time = 0.5 * static_cast<double>(k);
  if (!optional_arrays) {
    f.container = Container::periodic_box(dim, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
    return f;
  }
  f.set_observable({"tap", Scope::Frame, ValueType::Integer, 1, "", "tap number"}, k);
  f.set_observable({"cycle", Scope::Frame, ValueType::Integer, 1, "", "half-cycle"}, 2 * k);
  f.add("velocity").as<Coordinates>() = -f.position();
  f.add("angular_velocity").as<Coordinates>().setConstant(0.25);
  auto& supports = f.particles.add<ValueTable<std::int64_t>>(
      {"supports", Scope::Particle, ValueType::Integer, 2, "", "left, right support"});
  supports.col(0).setConstant(partner::none);
  supports.col(1).setConstant(partner::wall(Wall::ZLow));
  const Eigen::Index m = k + 1;  // frame k has k + 1 contacts
  PropertyTable& c = f.add_contacts(m);
  for (Eigen::Index q = 0; q < m; ++q) {
    f.contact_i()[q] = q;
    f.contact_j()[q] = q % 2 ? q + 1 : partner::wall(Wall::ZLow);
  }
  c.add<Eigen::ArrayXd>(*find_standard("overlap", Scope::Contact)).setConstant(1e-3);
  c.add<Coordinates>(*find_standard("normal_force", Scope::Contact)).setConstant(1.0);
  c.add(*find_standard("tangential_force", Scope::Contact));
  c.add<Coordinates>(*find_standard("point", Scope::Contact)).setConstant(0.5);
  f.container.shape = ContainerShape::Cylinder;
  f.container.lo = Eigen::Vector3d(-2, -2, 0);
  f.container.hi = Eigen::Vector3d(2, 2, 10);
  f.container.boundary[2][1] = Boundary::Open;
  f.container.cylinder_radius = 2.0;
  f.container.wall_offset = Eigen::Vector3d(0, 0, 0.1 * static_cast<double>(k));
  return f;
}

void write(const fs::path& path, long frames, int dim, Eigen::Index n, bool optional_arrays) {
  fs::remove(path);
  FrameWriter w(path, R"({"name": "layout sample", "seed": 1})");
  for (long k = 0; k < frames; ++k) w.append(sample(k, dim, n, optional_arrays));
  w.close();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_sample_frames OUTPUT_DIR\n";
    return 2;
  }
  try {
    const fs::path dir = argv[1];
    fs::create_directories(dir);
    write(dir / "full3d.h5", 3, 3, 5, true);
    write(dir / "bare2d.h5", 2, 2, 4, false);
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  return 0;
}
