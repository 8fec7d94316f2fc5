#include "frame_output.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include "granpipe/contact_rows.hpp"
#include "granpipe/errors.hpp"

namespace granpipe::dem {

namespace {

// Whether particles a and b touch: the force loop's test, on the same positions, so the
// same contacts.
bool touches(const Particles& p, int a, int b) {
  const double contact = p.radius[a] + p.radius[b];
  return !((p.x.col(a) - p.x.col(b)).squaredNorm() >= contact * contact);
}

// Whether particle a touches the wall of `slot`, and how deep (wall_contacts' test).
bool touches_wall(const Engine& e, int slot, int a, double& overlap, Vec3& n) {
  const Particles& p = e.particles();
  overlap = e.walls().overlap(slot, p.x.col(a), p.radius[a], e.wall_offset(), n);
  return !(overlap <= 0.0);
}

// How many rows pair_contacts and wall_contacts give: counted first, so that the rows take
// no more memory than they need (at 10^5 spheres and more, the frame's peak).
std::size_t touching_count(const Engine& e) {
  const Particles& p = e.particles();
  const NeighborList& list = e.neighbors();
  std::size_t count = 0;
  for (int a = 0; a < p.size(); ++a) {
    for (std::int32_t k = list.first[a]; k < list.first[a + 1]; ++k) {
      count += touches(p, a, list.partner[k]);
    }
    for (int slot = 0; slot < e.walls().count(); ++slot) {
      double overlap;
      Vec3 n;
      count += touches_wall(e, slot, a, overlap, n);
    }
  }
  return count;
}

void pair_contacts(const Engine& e, std::vector<ContactRow>& rows) {
  const Particles& p = e.particles();
  const NeighborList& list = e.neighbors();
  for (int a = 0; a < p.size(); ++a) {
    for (std::int32_t k = list.first[a]; k < list.first[a + 1]; ++k) {
      const int b = list.partner[k];
      if (!touches(p, a, b)) continue;
      const Vec3 d = p.x.col(a) - p.x.col(b);
      const double contact = p.radius[a] + p.radius[b];
      const double r = d.norm();
      const Vec3 n = d / r;
      const double* reaction = &list.reaction[3 * static_cast<std::size_t>(k)];
      const Vec3 on_a = -Vec3(reaction[0], reaction[1], reaction[2]);
      const Vec3 normal = on_a.dot(n) * n;
      const double overlap = contact - r;
      const Vec3 point = p.x.col(a) - (p.radius[a] - 0.5 * overlap) * n;
      // Rows name the smaller index first, with the forces on it.
      const double sign = p.tag[a] < p.tag[b] ? 1.0 : -1.0;
      rows.push_back({std::min(p.tag[a], p.tag[b]), std::max(p.tag[a], p.tag[b]), overlap,
                      sign * normal, sign * (on_a - normal), point});
    }
  }
}

void wall_contacts(const Engine& e, std::vector<ContactRow>& rows) {
  const Particles& p = e.particles();
  for (int slot = 0; slot < e.walls().count(); ++slot) {
    const std::int64_t wall = partner::wall(e.walls().wall_of_slot(slot));
    for (int a = 0; a < p.size(); ++a) {
      double overlap;
      Vec3 n;
      if (!touches_wall(e, slot, a, overlap, n)) continue;
      const Vec3 point = p.x.col(a) - (p.radius[a] - 0.5 * overlap) * n;
      rows.push_back({p.tag[a], wall, overlap, e.recorded_wall_normal()[slot].col(a),
                      e.recorded_wall_tangential()[slot].col(a), point});
    }
  }
}

void fill_particles(const Particles& p, Frame& frame) {
  frame.resize(p.size(), 3);
  Coordinates& x = frame.position();
  auto& v = frame.add("velocity").as<Coordinates>();
  auto& w = frame.add("angular_velocity").as<Coordinates>();
  for (int a = 0; a < p.size(); ++a) {
    const std::int32_t row = p.tag[a];
    x.row(row) = p.x.col(a).transpose();
    v.row(row) = p.v.col(a).transpose();
    w.row(row) = p.omega.col(a).transpose();
    frame.radius()[row] = p.radius[a];
    frame.species()[row] = p.species[a];
  }
}

// The drive's phase and the container's velocity, for analyses that cut a run into cycles.
void add_drive_observables(const Drive& drive, double t, Frame& frame) {
  static const Property cycles{
      "cycles", Scope::Frame, ValueType::Real,
      1,        "1",          "drive periods since the drive started, (t - start) f"};
  static const Property velocity{
      "container_velocity", Scope::Frame,
      ValueType::Real,      1,
      "length/time",        "vertical velocity of the vibrating container"};
  frame.set_observable(cycles, drive.cycles(t));
  frame.set_observable(velocity, drive.velocity(t)[2]);
}

}  // namespace

void fill_frame(const Engine& engine, Frame& frame) {
  if (engine.walls().count() > 0 && !engine.contacts_recorded()) {
    throw InternalError("dem: fill_frame at step " + std::to_string(engine.step()) +
                        ": the wall contacts of this step were not recorded "
                        "(Engine::record_contacts(true) before the last step)");
  }
  fill_particles(engine.particles(), frame);
  std::vector<ContactRow> rows;
  rows.reserve(touching_count(engine));
  pair_contacts(engine, rows);
  wall_contacts(engine, rows);
  std::sort(rows.begin(), rows.end(), [](const ContactRow& a, const ContactRow& b) {
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  fill_contact_table(rows, true, frame);
  frame.container = engine.walls().at(engine.time());
  add_drive_observables(engine.walls().drive(), engine.time(), frame);
  frame.time = engine.time();
  frame.step = engine.step();
}

}  // namespace granpipe::dem
