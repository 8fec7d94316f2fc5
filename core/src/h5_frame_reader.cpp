// FrameReader: frames from any H5MD file. granpipe's own files (with the /granpipe
// extension, docs/file-format.md) read back bit for bit; other tools' files give
// positions and whatever standard elements they hold, with radii set to a default and
// the container made from the H5MD box.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

#include "granpipe/errors.hpp"
#include "granpipe/frame_store.hpp"
#include "h5_dataset.hpp"
#include "h5_element.hpp"
#include "h5_frame_layout.hpp"

namespace granpipe {
namespace L = frame_layout;

namespace {

using RowMajor = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Checks that `shape` is [rows][item...] and returns rows.
hsize_t rows_of(const h5::Shape& shape, const h5::Shape& item, const std::string& path) {
  h5::Shape expected{0};
  expected.insert(expected.end(), item.begin(), item.end());
  if (shape.size() != expected.size() || !std::equal(item.begin(), item.end(), shape.begin() + 1)) {
    std::string want = "[frames";
    for (hsize_t n : item) want += ", " + std::to_string(n);
    throw h5::Error(path + ": expected shape " + want + "], got " + h5::format_shape(shape));
  }
  return shape[0];
}

void expect_item(const h5::Element& e, const h5::Shape& item) {
  if (e.item() != item) {
    throw h5::Error(e.path() + ": expected " + h5::format_shape(item) + " per frame, got " +
                    h5::format_shape(e.item()));
  }
}

// Opens normally, else as a SWMR reader: a file whose writer was killed (or is still
// running) refuses a normal open but reads back every frame it flushed.
h5::Object open_file(const std::string& name, bool& swmr) {
  std::error_code ec;
  if (!std::filesystem::exists(name, ec)) throw InputError(name + ": no such file");
  if (std::filesystem::is_directory(name, ec)) {
    throw InputError(name + ": expected an HDF5 file, got a directory");
  }
  if (!std::ifstream(name).good()) throw InputError(name + ": cannot be read (permissions?)");
  if (H5Fis_hdf5(name.c_str()) <= 0) {
    throw InputError(name + ": not an HDF5 file (no HDF5 signature)");
  }
  swmr = false;
  hid_t id = H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) {
    swmr = true;
    id = H5Fopen(name.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, H5P_DEFAULT);
  }
  if (id < 0) throw InputError(name + ": not a readable HDF5 file (truncated or corrupt)");
  return h5::Object(id);
}

// The /granpipe extension of one file: per-frame datasets, row k is frame k.
struct Extension {
  h5::Object radius, angular_velocity, tap, cycle, supports;
  h5::Object shape, lo, hi, boundary, cylinder_radius, cylinder_center, wall_offset,
      wall_velocity;
  h5::Object contact_i, contact_j, contact_overlap, contact_normal, contact_tangential,
      contact_point;
  std::vector<std::int64_t> contact_offset, contact_count;
  Eigen::Index angular_columns = 0;
};

}  // namespace

struct FrameReader::Impl {
  std::string name;
  h5::Object file;
  FrameFileInfo info;
  double default_radius = 0.5;
  std::optional<h5::Element> position, velocity, species, id, edges;
  std::vector<std::int64_t> steps;
  std::vector<double> times;
  std::array<bool, 3> periodic{};
  std::optional<Extension> ext;

  void open(const std::string& group);
  std::string choose_group(const std::string& group) const;
  void open_elements(const std::string& base);
  void open_box(const std::string& base);
  void open_extension();
  hsize_t extension_rows(const std::string& path, const h5::Shape& item, h5::Object& out);
  void map_foreign_elements();
  Frame read(long k) const;
  Container box_container(long k, const Frame& f) const;
  Container extension_container(long k) const;
  Contacts read_contacts(long k) const;
};

std::string FrameReader::Impl::choose_group(const std::string& group) const {
  h5::Object particles = h5::open_group(file.id(), L::kParticles);
  const std::vector<std::string> groups = h5::members(particles.id(), L::kParticles);
  std::string list;
  for (const auto& g : groups) list += (list.empty() ? "" : ", ") + g;
  if (!group.empty()) {
    if (!h5::is_group(file.id(), L::particles(group))) {
      throw h5::Error(L::particles(group) + ": no such particles group (the file has: " +
                      (list.empty() ? "none" : list) + ")");
    }
    return group;
  }
  if (std::find(groups.begin(), groups.end(), L::kGroup) != groups.end()) return L::kGroup;
  if (groups.size() == 1) return groups.front();
  throw h5::Error(L::kParticles + ": " +
                  (groups.empty() ? std::string("no particles group")
                                  : "several particles groups (" + list + "); choose one"));
}

void FrameReader::Impl::open_elements(const std::string& base) {
  position = h5::Element::open(file.id(), base + "/position");
  if (!position) throw h5::Error(base + "/position: missing (the file has no particle positions)");
  const h5::Shape item = position->item();
  if (item.size() != 2 || (item[1] != 2 && item[1] != 3)) {
    throw h5::Error(position->path() + ": expected positions of shape [frames][N][2 or 3], got " +
                    h5::format_shape(item) + " per frame");
  }
  info.particles = static_cast<long>(item[0]);
  info.dim = static_cast<int>(item[1]);
  info.frames = static_cast<long>(position->samples());
  if (position->timed()) {
    steps = position->steps();
    times = position->times();
  } else {
    steps = {0};
  }
  const auto n = static_cast<hsize_t>(info.particles), d = static_cast<hsize_t>(info.dim);
  velocity = h5::Element::open(file.id(), base + "/velocity");
  if (velocity) expect_item(*velocity, {n, d});
  species = h5::Element::open(file.id(), base + "/species");
  if (species) expect_item(*species, {n});
  id = h5::Element::open(file.id(), base + "/id");
  if (id) expect_item(*id, {n});
}

void FrameReader::Impl::open_box(const std::string& base) {
  const std::string path = base + "/box";
  if (!h5::is_group(file.id(), path)) {
    throw h5::Error(path + ": missing (H5MD puts a box in every particles group)");
  }
  h5::Object box = h5::open_group(file.id(), path);
  if (h5::has_attribute(box.id(), "dimension")) {
    const auto dim = h5::read_integer_attribute(box.id(), path, "dimension");
    if (dim.size() != 1 || dim[0] != info.dim) {
      throw h5::Error(path + "@dimension: expected " + std::to_string(info.dim) +
                      " (the position dimension), got " +
                      (dim.empty() ? std::string("nothing") : std::to_string(dim[0])));
    }
  }
  const auto boundary = h5::read_string_attribute(box.id(), path, "boundary");
  if (boundary.size() != static_cast<std::size_t>(info.dim)) {
    throw h5::Error(path + "@boundary: expected " + std::to_string(info.dim) + " entries, got " +
                    std::to_string(boundary.size()));
  }
  bool any_periodic = false;
  for (int a = 0; a < info.dim; ++a) {
    if (boundary[a] != "periodic" && boundary[a] != "none") {
      throw h5::Error(path + "@boundary: expected \"periodic\" or \"none\", got \"" + boundary[a] +
                      "\"");
    }
    periodic[a] = boundary[a] == "periodic";
    any_periodic = any_periodic || periodic[a];
  }
  edges = h5::Element::open(file.id(), path + "/edges");
  if (!edges) {
    if (any_periodic) throw h5::Error(path + "/edges: missing (a periodic box needs its edges)");
    return;
  }
  const auto d = static_cast<hsize_t>(info.dim);
  if (edges->item() != h5::Shape{d} && edges->item() != h5::Shape{d, d}) {
    throw h5::Error(edges->path() + ": expected " + h5::format_shape({d}) + " or " +
                    h5::format_shape({d, d}) + " per frame, got " +
                    h5::format_shape(edges->item()));
  }
}

hsize_t FrameReader::Impl::extension_rows(const std::string& path, const h5::Shape& item,
                                          h5::Object& out) {
  out = h5::open_dataset(file.id(), path);
  return rows_of(h5::shape_of(out.id(), path), item, path);
}

void FrameReader::Impl::open_extension() {
  h5::Object group = h5::open_group(file.id(), L::kExtension);
  const auto version = h5::read_integer_attribute(group.id(), L::kExtension, L::kVersionAttr);
  if (version.empty() || version[0] != L::kVersionMajor) {
    throw h5::Error(L::kExtension + "@version: expected " + std::to_string(L::kVersionMajor) +
                    ".x, got " + (version.empty() ? "nothing" : std::to_string(version[0])) +
                    " (written by another granpipe version)");
  }
  info.granpipe_file = true;
  if (h5::has_attribute(group.id(), L::kCompleteAttr)) {
    const auto flag = h5::read_integer_attribute(group.id(), L::kExtension, L::kCompleteAttr);
    info.complete = info.complete && !flag.empty() && flag[0] == 1;
  } else {
    info.complete = false;
  }
  if (!position) return;  // closed before its first frame: no frames at all

  Extension x;
  const auto n = static_cast<hsize_t>(info.particles), d = static_cast<hsize_t>(info.dim);
  hsize_t frames = static_cast<hsize_t>(info.frames);
  auto rows = [&](const std::string& path, const h5::Shape& item, h5::Object& out) {
    frames = std::min(frames, extension_rows(path, item, out));
  };
  rows(L::kRadius, {n}, x.radius);
  if (h5::is_dataset(file.id(), L::kAngularVelocity)) {
    h5::Object ds = h5::open_dataset(file.id(), L::kAngularVelocity);
    const h5::Shape shape = h5::shape_of(ds.id(), L::kAngularVelocity);
    x.angular_columns = shape.size() == 3 ? static_cast<Eigen::Index>(shape[2]) : 0;
    rows(L::kAngularVelocity, {n, static_cast<hsize_t>(x.angular_columns)}, x.angular_velocity);
  }
  rows(L::kTap, {}, x.tap);
  rows(L::kCycle, {}, x.cycle);
  if (h5::is_dataset(file.id(), L::kSupports)) rows(L::kSupports, {n, 2}, x.supports);
  rows(L::kShape, {}, x.shape);
  rows(L::kLo, {3}, x.lo);
  rows(L::kHi, {3}, x.hi);
  rows(L::kBoundary, {3, 2}, x.boundary);
  rows(L::kCylinderRadius, {}, x.cylinder_radius);
  rows(L::kCylinderCenter, {2}, x.cylinder_center);
  rows(L::kWallOffset, {3}, x.wall_offset);
  rows(L::kWallVelocity, {3}, x.wall_velocity);
  const bool contacts = h5::is_group(file.id(), L::kContacts);
  hsize_t contact_rows = 0;
  if (contacts) {
    h5::Object offset, count;
    rows(L::kContactOffset, {}, offset);
    rows(L::kContactCount, {}, count);
    contact_rows = extension_rows(L::kContactI, {}, x.contact_i);
    contact_rows = std::min(contact_rows, extension_rows(L::kContactJ, {}, x.contact_j));
    contact_rows = std::min(contact_rows, extension_rows(L::kContactOverlap, {}, x.contact_overlap));
    contact_rows = std::min(contact_rows, extension_rows(L::kContactNormal, {d}, x.contact_normal));
    contact_rows =
        std::min(contact_rows, extension_rows(L::kContactTangential, {d}, x.contact_tangential));
    contact_rows = std::min(contact_rows, extension_rows(L::kContactPoint, {d}, x.contact_point));
    x.contact_offset = h5::read_integer_rows(offset.id(), L::kContactOffset, 0, frames);
    x.contact_count = h5::read_integer_rows(count.id(), L::kContactCount, 0, frames);
  }
  // Every element of a granpipe file shares position's clock, so frame k is row k of
  // everything; a killed writer may leave some datasets a frame ahead of others.
  for (auto* e : {&velocity, &species, &id, &edges}) {
    if (*e) {
      frames = std::min<hsize_t>(frames, (*e)->samples());
      (*e)->map_identity();
    }
  }
  // A row whose step is still the fill value was extended but never committed.
  while (frames > 0 && steps[frames - 1] == L::kUnwrittenStep) --frames;
  while (contacts && frames > 0 &&
         x.contact_offset[frames - 1] + x.contact_count[frames - 1] >
             static_cast<std::int64_t>(contact_rows)) {
    if (info.complete) {
      throw h5::Error(L::kContacts + ": frame " + std::to_string(frames - 1) +
                      " points past the end of the contact arrays (damaged file)");
    }
    --frames;
  }
  info.frames = static_cast<long>(frames);
  info.has_radius = true;
  info.has_angular_velocity = x.angular_columns > 0;
  info.has_supports = x.supports.valid();
  info.has_contacts = contacts;
  ext = std::move(x);
}

void FrameReader::Impl::map_foreign_elements() {
  // Other tools may sample elements on their own clocks; an optional element counts
  // only when it has a sample at every frame's step.
  const std::vector<std::int64_t> frame_steps(steps.begin(), steps.begin() + info.frames);
  for (auto* e : {&velocity, &species, &id}) {
    if (*e && !(*e)->map_by_step(frame_steps)) e->reset();
  }
  if (edges && !edges->map_by_step(frame_steps)) {
    throw h5::Error(edges->path() + ": the box is not stored at every step of the positions");
  }
}

void FrameReader::Impl::open(const std::string& group) {
  bool swmr = false;
  file = open_file(name, swmr);
  info.path = name;
  info.complete = !swmr;
  if (h5::is_group(file.id(), "/h5md/creator")) {
    h5::Object creator = h5::open_group(file.id(), "/h5md/creator");
    for (const char* attr : {"name", "version"}) {
      if (!h5::has_attribute(creator.id(), attr)) continue;
      const auto text = h5::read_string_attribute(creator.id(), "/h5md/creator", attr);
      if (!text.empty()) info.creator += (info.creator.empty() ? "" : " ") + text[0];
    }
  }
  const bool ours = h5::is_group(file.id(), L::kExtension);
  if (ours && !h5::is_group(file.id(), L::kParticles) && group.empty()) {
    open_extension();  // a granpipe file closed before its first frame
    return;
  }
  if (!h5::is_group(file.id(), L::kParticles)) {
    throw h5::Error(L::kParticles + ": missing (not an H5MD file with particles)");
  }
  info.group = choose_group(group);
  const std::string base = L::particles(info.group);
  open_elements(base);
  open_box(base);
  if (ours && info.group == L::kGroup) {
    open_extension();
  } else {
    map_foreign_elements();
  }
  info.has_velocity = velocity.has_value();
}

// H5MD stores a box's edge lengths but not its origin. Periodic sides need none (positions
// are wrapped where used); walls do: they go at [0, L] or, as some codes centre their
// boxes, [-L/2, L/2], whichever holds every particle centre. Anything else is refused
// rather than measured against walls in the wrong place.
namespace {
void place_walls(Container& c, int a, const Frame& f, const std::string& dataset, long k) {
  const double lo = f.position.col(a).minCoeff(), hi = f.position.col(a).maxCoeff();
  const double length = c.hi[a];
  for (double origin : {0.0, -0.5 * length}) {
    if (lo >= origin && hi <= origin + length) {
      c.lo[a] = origin;
      c.hi[a] = origin + length;
      return;
    }
  }
  throw h5::Error(dataset + ": frame " + std::to_string(k) + ": expected particle centres inside a box of edge " +
                  std::to_string(length) + " along axis " + std::to_string(a) + " (at [0, L] or [-L/2, L/2]), got " +
                  std::to_string(lo) + " to " + std::to_string(hi));
}
}  // namespace

Container FrameReader::Impl::box_container(long k, const Frame& f) const {
  Container c;
  const int d = info.dim;
  if (!edges) {
    // A box with every side "none" and no edges: open on all sides, spanning the particles.
    for (int a = 0; a < d; ++a) {
      c.boundary[a] = {Boundary::Open, Boundary::Open};
      if (f.size() > 0) {
        c.lo[a] = (f.position.col(a) - f.radius).minCoeff();
        c.hi[a] = (f.position.col(a) + f.radius).maxCoeff();
      }
    }
    return c;
  }
  std::vector<double> e(edges->item().size() == 2 ? d * d : d);
  edges->read(k, e.data());
  c.lo.setZero();
  for (int a = 0; a < d; ++a) {
    if (e.size() == static_cast<std::size_t>(d * d)) {
      for (int b = 0; b < d; ++b) {
        if (a != b && e[a * d + b] != 0.0) {
          throw h5::Error(edges->path() + ": triclinic boxes are not supported (frame " +
                          std::to_string(k) + ")");
        }
      }
      c.hi[a] = e[a * d + a];
    } else {
      c.hi[a] = e[a];
    }
    const Boundary b = periodic[a] ? Boundary::Periodic : Boundary::Wall;
    c.boundary[a] = {b, b};
    if (!periodic[a] && f.size() > 0) place_walls(c, a, f, edges->path(), k);
  }
  return c;
}

Container FrameReader::Impl::extension_container(long k) const {
  const Extension& x = *ext;
  const auto row = static_cast<hsize_t>(k);
  Container c;
  const std::int64_t shape = h5::read_integer_rows(x.shape.id(), L::kShape, row, 1).at(0);
  if (shape != static_cast<std::int64_t>(ContainerShape::Box) &&
      shape != static_cast<std::int64_t>(ContainerShape::Cylinder)) {
    throw h5::Error(L::kShape + ": unknown container shape " + std::to_string(shape));
  }
  c.shape = static_cast<ContainerShape>(shape);
  auto reals = [&](const h5::Object& ds, const std::string& path, double* out) {
    h5::read_rows(ds.id(), path, H5T_NATIVE_DOUBLE, row, 1, out);
  };
  reals(x.lo, L::kLo, c.lo.data());
  reals(x.hi, L::kHi, c.hi.data());
  reals(x.cylinder_radius, L::kCylinderRadius, &c.cylinder_radius);
  reals(x.cylinder_center, L::kCylinderCenter, c.cylinder_center.data());
  reals(x.wall_offset, L::kWallOffset, c.wall_offset.data());
  reals(x.wall_velocity, L::kWallVelocity, c.wall_velocity.data());
  const auto sides = h5::read_integer_rows(x.boundary.id(), L::kBoundary, row, 1);
  for (int a = 0; a < 3; ++a) {
    for (int s = 0; s < 2; ++s) {
      const std::int64_t b = sides[a * 2 + s];
      if (b < 0 || b > static_cast<std::int64_t>(Boundary::Open)) {
        throw h5::Error(L::kBoundary + ": unknown boundary kind " + std::to_string(b));
      }
      c.boundary[a][s] = static_cast<Boundary>(b);
    }
  }
  return c;
}

Contacts FrameReader::Impl::read_contacts(long k) const {
  const Extension& x = *ext;
  const auto first = static_cast<hsize_t>(x.contact_offset[k]);
  const auto m = static_cast<Eigen::Index>(x.contact_count[k]);
  Contacts c;
  c.resize(m, info.dim);
  const auto rows = static_cast<hsize_t>(m);
  h5::read_rows(x.contact_i.id(), L::kContactI, H5T_NATIVE_INT64, first, rows, c.i.data());
  h5::read_rows(x.contact_j.id(), L::kContactJ, H5T_NATIVE_INT64, first, rows, c.j.data());
  h5::read_rows(x.contact_overlap.id(), L::kContactOverlap, H5T_NATIVE_DOUBLE, first, rows,
                c.overlap.data());
  RowMajor buffer(m, info.dim);
  auto vectors = [&](const h5::Object& ds, const std::string& path, Coordinates& out) {
    h5::read_rows(ds.id(), path, H5T_NATIVE_DOUBLE, first, rows, buffer.data());
    out = buffer;
  };
  vectors(x.contact_normal, L::kContactNormal, c.normal_force);
  vectors(x.contact_tangential, L::kContactTangential, c.tangential_force);
  vectors(x.contact_point, L::kContactPoint, c.point);
  return c;
}

Frame FrameReader::Impl::read(long k) const {
  const Eigen::Index n = info.particles;
  const int d = info.dim;
  Frame f;
  f.dim = d;
  RowMajor buffer(n, d);
  position->read(k, buffer.data());
  f.position = buffer;
  if (velocity) {
    velocity->read(k, buffer.data());
    f.velocity = buffer;
  }
  f.id = id ? Eigen::Map<const IndexArray>(id->read_integers(k).data(), n).eval()
            : IndexArray::LinSpaced(n, 0, n - 1);
  f.species = IntArray::Zero(n);
  if (species) {
    const auto s = species->read_integers(k);
    for (Eigen::Index p = 0; p < n; ++p) f.species[p] = static_cast<std::int32_t>(s[p]);
  }
  f.step = steps[k];
  if (!times.empty()) f.time = times[k];

  if (!ext) {
    f.radius = Eigen::ArrayXd::Constant(n, default_radius);
    f.container = box_container(k, f);
    return f;
  }
  const Extension& x = *ext;
  const auto row = static_cast<hsize_t>(k);
  f.radius.resize(n);
  h5::read_rows(x.radius.id(), L::kRadius, H5T_NATIVE_DOUBLE, row, 1, f.radius.data());
  if (x.angular_columns) {
    RowMajor w(n, x.angular_columns);
    h5::read_rows(x.angular_velocity.id(), L::kAngularVelocity, H5T_NATIVE_DOUBLE, row, 1,
                  w.data());
    f.angular_velocity = w;
  }
  f.tap = h5::read_integer_rows(x.tap.id(), L::kTap, row, 1).at(0);
  f.cycle = h5::read_integer_rows(x.cycle.id(), L::kCycle, row, 1).at(0);
  if (x.supports.valid()) {
    Eigen::Array<std::int64_t, Eigen::Dynamic, 2, Eigen::RowMajor> pairs(n, 2);
    h5::read_rows(x.supports.id(), L::kSupports, H5T_NATIVE_INT64, row, 1, pairs.data());
    f.supports = Supports{pairs.col(0), pairs.col(1)};
  }
  f.container = extension_container(k);
  if (info.has_contacts) f.contacts = read_contacts(k);
  return f;
}

FrameReader::FrameReader(const std::filesystem::path& path, const std::string& group,
                         double default_radius)
    : impl_(std::make_unique<Impl>()) {
  h5::silence_error_stack();
  impl_->name = path.string();
  impl_->default_radius = default_radius;
  h5::input_errors_of(impl_->name, [&] { impl_->open(group); });
}

FrameReader::~FrameReader() = default;

const FrameFileInfo& FrameReader::info() const { return impl_->info; }

Frame FrameReader::read(long index) const {
  h5::silence_error_stack();
  if (index < 0 || index >= impl_->info.frames) {
    throw InternalError(impl_->name + ": frame " + std::to_string(index) + " requested, the file has " +
                        std::to_string(impl_->info.frames));
  }
  return h5::input_errors_of(impl_->name, [&] { return impl_->read(index); });
}

}  // namespace granpipe
