#pragma once
// Tiny frames for the vtk writer's tests: three spheres with a velocity, an integer and a
// real published-like column (one value NaN), a contact between particles 0 and 1 and one
// between particle 2 and the base; the second frame is the first, later.
#include <cmath>

#include "granpipe/frame.hpp"

namespace granpipe::test {

inline Frame vtk_sample_frame() {
  Frame f;
  f.resize(3, 3);
  f.container = Container::open_top_box(3, Eigen::Vector3d(-1, -1, -0.5), Eigen::Vector3d(2, 2, 2));
  f.position() << 0, 0, 0, 1, 0, 0, 0.5, 1, 0.25;
  f.radius() << 0.5, 0.5, 0.25;
  f.id() << 10, 11, 12;
  f.species() << 0, 0, 1;
  f.add("velocity").as<ValueTable<double>>() << 1, 2, 3, 0, 0, -1, 0.5, 0, 0;
  f.particles.add<Values<std::int64_t>>(
      {"network", Scope::Particle, ValueType::Integer, 1, "", "force network"})
      << 0,
      0, -1;
  f.particles.add<Values<double>>(
      {"voronoi_volume", Scope::Particle, ValueType::Real, 1, "length^3", "Voronoi cell volume"})
      << 1.5,
      2.5, std::nan("");
  f.add_contacts(2);
  f.contact_i() << 0, 2;
  f.contact_j() << 1, partner::wall(Wall::ZLow);
  f.contacts->add<Values<double>>(*find_standard("overlap", Scope::Contact)) << 0.125, 0.01;
  f.contacts->add<ValueTable<double>>(*find_standard("normal_force", Scope::Contact)) << -2, 0, 0,
      0, 0, 3;
  f.contacts->add<Values<std::int64_t>>(
      {"mst_pass", Scope::Contact, ValueType::Integer, 1, "", "first MST pass"})
      << 1,
      0;
  f.time = 0.5;
  f.step = 100;
  return f;
}

inline Frame vtk_sample_frame_later() {
  Frame f = vtk_sample_frame();
  f.time = 0.75;
  f.step = 150;
  return f;
}

}  // namespace granpipe::test
