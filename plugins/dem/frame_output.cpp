#include "frame_output.hpp"

#include <algorithm>
#include <cmath>
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

// Whether particle a touches the wall of `slot` (the walls moved by `offset`), and how deep.
bool touches_wall(const Engine& e, const Eigen::Vector3d& offset, int slot, int a, double& overlap,
                  Vec3& n) {
  const Particles& p = e.particles();
  overlap = e.walls().overlap(slot, p.x.col(a), p.radius[a], offset, n);
  return !(overlap <= 0.0);
}

// A contact of the frame before its values: its rows (by tag, the smaller first, or the
// particle and its wall) and where the values come from: listed pair k, or particle a
// against the wall of `slot`. A sixth of a row's size, so that a frame of 10^6 spheres
// holds its contacts once as values (in the table) and once as keys, not twice as values.
struct ContactKey {
  std::int32_t i, j;  // tags, or a tag and its wall's code (partner::wall)
  std::int32_t from;  // k, or a
  std::int32_t slot;  // -1 for a pair
};

// Calls visit(key) for every contact, pairs by owner, then walls by slot.
template <class Visit>
void for_each_contact(const Engine& e, const Eigen::Vector3d& offset, Visit visit) {
  const Particles& p = e.particles();
  const NeighborList& list = e.neighbors();
  for (int a = 0; a < p.size(); ++a) {
    for (std::int32_t k = list.first[a]; k < list.first[a + 1]; ++k) {
      const int b = list.partner[k];
      if (touches(p, a, b))
        visit({std::min(p.tag[a], p.tag[b]), std::max(p.tag[a], p.tag[b]), k, -1});
    }
  }
  for (int slot = 0; slot < e.walls().count(); ++slot) {
    const auto wall = static_cast<std::int32_t>(partner::wall(e.walls().wall_of_slot(slot)));
    for (int a = 0; a < p.size(); ++a) {
      double overlap;
      Vec3 n;
      if (touches_wall(e, offset, slot, a, overlap, n)) visit({p.tag[a], wall, a, slot});
    }
  }
}

// The contacts' keys by rows, counted first so that the keys take exactly their room.
std::vector<ContactKey> contact_keys(const Engine& e, const Eigen::Vector3d& offset) {
  std::size_t count = 0;
  for_each_contact(e, offset, [&](const ContactKey&) { ++count; });
  std::vector<ContactKey> keys;
  keys.reserve(count);
  for_each_contact(e, offset, [&](const ContactKey& key) { keys.push_back(key); });
  std::sort(keys.begin(), keys.end(), [](const ContactKey& x, const ContactKey& y) {
    return x.i != y.i ? x.i < y.i : x.j < y.j;
  });
  return keys;
}

// The row of listed pair k, whose owner is particle a (the force loop stored the force on
// the partner, b, in the pair's reaction slot, which the step a frame shows keeps).
ContactRow pair_row(const Engine& e, std::int32_t k) {
  const Particles& p = e.particles();
  const NeighborList& list = e.neighbors();
  const int a = list.owner[static_cast<std::size_t>(k)],
            b = list.partner[static_cast<std::size_t>(k)];
  const Vec3 d = p.x.col(a) - p.x.col(b);
  const double contact = p.radius[a] + p.radius[b];
  const double r = d.norm();
  const Vec3 n = d / r;
  const double* reaction = &list.incoming[static_cast<std::size_t>(list.reaction_stride) *
                                          static_cast<std::size_t>(list.reaction_slot[k])];
  const Vec3 on_a = -Vec3(reaction[0], reaction[1], reaction[2]);
  const Vec3 normal = on_a.dot(n) * n;
  const double overlap = contact - r;
  const Vec3 point = p.x.col(a) - (p.radius[a] - 0.5 * overlap) * n;
  // Rows name the smaller index first, with the forces on it.
  const double sign = p.tag[a] < p.tag[b] ? 1.0 : -1.0;
  return {std::min(p.tag[a], p.tag[b]),
          std::max(p.tag[a], p.tag[b]),
          overlap,
          sign * normal,
          sign * (on_a - normal),
          point};
}

ContactRow wall_row(const Engine& e, const Eigen::Vector3d& offset, std::int32_t a, int slot) {
  const Particles& p = e.particles();
  double overlap;
  Vec3 n;
  touches_wall(e, offset, slot, a, overlap, n);
  const Vec3 point = p.x.col(a) - (p.radius[a] - 0.5 * overlap) * n;
  return {p.tag[a],
          partner::wall(e.walls().wall_of_slot(slot)),
          overlap,
          e.recorded_wall_normal()[slot].col(a),
          e.recorded_wall_tangential()[slot].col(a),
          point};
}

// The wall contacts' rows, in the keys' order: walls are touched by few particles, and
// read out first they let the engine's records (two vectors per particle and wall) go
// before the table takes its room.
std::vector<ContactRow> wall_rows(const Engine& e, const Eigen::Vector3d& offset,
                                  const std::vector<ContactKey>& keys) {
  std::vector<ContactRow> rows;
  for (const ContactKey& key : keys) {
    if (key.slot >= 0) rows.push_back(wall_row(e, offset, key.from, key.slot));
  }
  return rows;
}

void fill_contacts(Engine& e, Frame& frame) {
  const Eigen::Vector3d offset = e.wall_offset();  // the drive's, once for every wall test
  const std::vector<ContactKey> keys = contact_keys(e, offset);
  const std::vector<ContactRow> walls = wall_rows(e, offset, keys);
  e.release_contact_records();
  ContactTableWriter table(frame, static_cast<Eigen::Index>(keys.size()), true);
  std::size_t w = 0;
  for (std::size_t r = 0; r < keys.size(); ++r) {
    const ContactKey& key = keys[r];
    table.set(static_cast<Eigen::Index>(r), key.slot < 0 ? pair_row(e, key.from) : walls[w++]);
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
      "cycles",
      Scope::Frame,
      ValueType::Real,
      1,
      "1",
      "drive periods since the drive started, (t - start) f; NaN without a drive"};
  static const Property velocity{
      "container_velocity", Scope::Frame,
      ValueType::Real,      1,
      "length/time",        "vertical velocity of the vibrating container"};
  // Without a drive there are no cycles: 0 put every frame of a run at cycle 0.
  frame.set_observable(cycles, drive.angular_frequency > 0.0 ? drive.cycles(t) : std::nan(""));
  frame.set_observable(velocity, drive.velocity(t)[2]);
}

}  // namespace

void fill_frame(Engine& engine, Frame& frame) {
  if (engine.walls().count() > 0 && !engine.contacts_recorded()) {
    throw InternalError("dem: fill_frame at step " + std::to_string(engine.step()) +
                        ": the wall contacts of this step were not recorded "
                        "(Engine::record_contacts(true) before the last step)");
  }
  // A large run holds at once its engine and no more than one frame: the previous frame's
  // columns go first, and the contacts (which free the engine's wall-force records) are
  // made before the particles' columns.
  frame.resize(0, 3);
  Frame contacts;
  fill_contacts(engine, contacts);
  fill_particles(engine.particles(), frame);
  frame.contacts = std::move(contacts.contacts);
  frame.container = engine.walls().at(engine.time());
  add_drive_observables(engine.walls().drive(), engine.time(), frame);
  frame.time = engine.time();
  frame.step = engine.step();
}

}  // namespace granpipe::dem
