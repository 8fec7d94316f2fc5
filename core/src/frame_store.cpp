// FrameWriter: frames.h5 as H5MD 1.1 plus the /granpipe extension (docs/file-format.md).
//
// Crash safety rests on three things: HDF5's SWMR mode (a killed writer leaves a file
// whose flushed state is consistent), a fixed write order within a frame (every other
// dataset first, then time, then step), and the reader counting only frames present in
// every dataset. The `complete` attribute is set only by close(), after SWMR has ended.
#include <algorithm>
#include <cstdlib>
#include <optional>

#include "granpipe/errors.hpp"
#include "granpipe/frame_store.hpp"
#include "granpipe/version.hpp"
#include "h5_dataset.hpp"
#include "h5_frame_layout.hpp"

namespace granpipe {
namespace L = frame_layout;

namespace {

using RowMajor = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// What every frame of one file carries, fixed by the first frame.
struct Layout {
  Eigen::Index particles = 0;
  int dim = 0;
  bool velocity = false;
  Eigen::Index angular_columns = 0;  // 0: no angular velocity
  bool contacts = false;
  bool supports = false;

  static Layout of(const Frame& f) {
    return {f.size(), f.dim, f.velocity.has_value(),
            f.angular_velocity ? f.angular_velocity->cols() : 0, f.contacts.has_value(),
            f.supports.has_value()};
  }
  bool operator==(const Layout&) const = default;
};

std::string describe(const Layout& l) {
  std::string s = std::to_string(l.particles) + " particles in " + std::to_string(l.dim) + "D";
  if (l.velocity) s += ", velocities";
  if (l.angular_columns) s += ", angular velocities (" + std::to_string(l.angular_columns) + ")";
  if (l.contacts) s += ", contacts";
  if (l.supports) s += ", supports";
  return s;
}

// A frame whose arrays disagree in size would make the writer read out of bounds.
void check_sizes(const Frame& f, const std::string& where) {
  const Eigen::Index n = f.size();
  auto require = [&](bool ok, const char* what) {
    if (!ok) throw InternalError(where + ": frame arrays disagree in size (" + what + ")");
  };
  require(f.dim == 2 || f.dim == 3, "dimension is not 2 or 3");
  require(f.position.cols() == f.dim, "position columns");
  require(f.radius.size() == n && f.id.size() == n && f.species.size() == n,
          "radius, id or species");
  if (f.velocity) require(f.velocity->rows() == n && f.velocity->cols() == f.dim, "velocity");
  if (f.angular_velocity) require(f.angular_velocity->rows() == n, "angular velocity");
  if (f.supports) require(f.supports->left.size() == n && f.supports->right.size() == n,
                          "supports");
  if (f.contacts) {
    const Contacts& c = *f.contacts;
    const Eigen::Index m = c.size();
    require(c.j.size() == m && c.overlap.size() == m, "contact i, j, overlap");
    for (const Coordinates* a : {&c.normal_force, &c.tangential_force, &c.point}) {
      require(a->rows() == m && a->cols() == f.dim, "contact forces or points");
    }
  }
}

// Rows per chunk: about 16 KiB per chunk, at most `max_rows`. Small chunks keep small
// files small; one frame per chunk for large frames.
hsize_t chunk_rows(const h5::Shape& item, std::size_t bytes, hsize_t max_rows) {
  hsize_t row = bytes;
  for (hsize_t n : item) row *= std::max<hsize_t>(n, 1);
  return std::clamp<hsize_t>((16 * 1024) / row, 1, max_rows);
}

constexpr hsize_t kFrameRows = 256;     // per-frame datasets
constexpr hsize_t kContactRows = 4096;  // concatenated contact arrays

hid_t file_access_latest() {
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  // SWMR needs the latest file format.
  if (fapl >= 0) H5Pset_libver_bounds(fapl, H5F_LIBVER_LATEST, H5F_LIBVER_LATEST);
  return fapl;
}

}  // namespace

struct FrameWriter::Impl {
  struct Series {
    std::string path;
    h5::Object dataset;
    void append(hid_t mem_type, const void* data, hsize_t rows = 1) const {
      h5::append_rows(dataset.id(), path, mem_type, data, rows);
    }
  };
  // Every dataset of the file, created together when the first frame arrives (SWMR
  // forbids creating objects once it has started).
  struct Datasets {
    Series step, time, position, velocity, species, id, edges;
    Series radius, angular_velocity, tap, cycle, supports;
    Series shape, lo, hi, boundary, cylinder_radius, cylinder_center, wall_offset,
        wall_velocity;
    Series contact_offset, contact_count, contact_i, contact_j, contact_overlap,
        contact_normal, contact_tangential, contact_point;
  };

  std::string name;
  h5::Object file;
  h5::Object boundary_type = L::boundary_type(), shape_type = L::shape_type();
  std::optional<Datasets> ds;
  std::optional<Layout> layout;
  long frames = 0;
  long long contacts_written = 0;
  bool closed = false;

  Series series(const std::string& path, hid_t type, const h5::Shape& item, hsize_t max_rows,
                hid_t fill_type = H5I_INVALID_HID, const void* fill = nullptr) {
    return {path, h5::create_series(file.id(), path, type, item,
                                    chunk_rows(item, H5Tget_size(type), max_rows), fill_type,
                                    fill)};
  }
  // An H5MD time-dependent element sharing position's step and time (hard links, as
  // the H5MD specification asks of elements sampled together).
  void element(const std::string& path) {
    h5::create_group(file.id(), path);
    const std::string position = L::particles(L::kGroup) + "/position";
    for (const char* s : {"/step", "/time"}) {
      h5::check(H5Lcreate_hard(file.id(), (position + s).c_str(), file.id(), (path + s).c_str(),
                               H5P_DEFAULT, H5P_DEFAULT),
                path + s + ": cannot link");
    }
  }

  void create_file(const std::string& provenance);
  void create_datasets(const Frame& first);
  void write(const Frame& f);
};

void FrameWriter::Impl::create_file(const std::string& provenance) {
  h5::Object fapl = h5::owned(file_access_latest(), "cannot make the file access list");
  file = h5::owned(H5Fcreate(name.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, fapl.id()),
                   "cannot create the file (does its directory exist and is it writable?)");
  h5::Object h5md = h5::create_group(file.id(), "/h5md");
  h5::write_attribute(h5md.id(), "version", std::vector<int>{1, 1});
  h5::Object author = h5::create_group(file.id(), "/h5md/author");
  const char* user = std::getenv("USER");
  h5::write_attribute(author.id(), "name", std::string(user && *user ? user : "unknown"));
  h5::Object creator = h5::create_group(file.id(), "/h5md/creator");
  h5::write_attribute(creator.id(), "name", std::string("granpipe"));
  h5::write_attribute(creator.id(), "version", std::string(GRANPIPE_VERSION));

  h5::Object ext = h5::create_group(file.id(), L::kExtension);
  h5::write_attribute(ext.id(), L::kVersionAttr,
                      std::vector<int>{L::kVersionMajor, L::kVersionMinor});
  h5::write_attribute(ext.id(), L::kCompleteAttr, 0);
  h5::write_text_attribute(ext.id(), L::kProvenanceAttr, provenance);
  h5::check(H5Fflush(file.id(), H5F_SCOPE_GLOBAL), "cannot flush");
}

void FrameWriter::Impl::create_datasets(const Frame& f) {
  const Layout& l = *layout;
  const auto n = static_cast<hsize_t>(l.particles), d = static_cast<hsize_t>(l.dim);
  const hid_t f64 = H5T_IEEE_F64LE, i64 = H5T_STD_I64LE, i32 = H5T_STD_I32LE;
  const std::string all = L::particles(L::kGroup);
  Datasets s;

  h5::create_group(file.id(), L::kParticles);
  h5::create_group(file.id(), all);
  h5::create_group(file.id(), all + "/position");
  const long long unwritten = L::kUnwrittenStep;
  s.step = series(all + "/position/step", i64, {}, kFrameRows, H5T_NATIVE_LLONG, &unwritten);
  s.time = series(all + "/position/time", f64, {}, kFrameRows);
  s.position = series(all + "/position/value", f64, {n, d}, kFrameRows);
  if (l.velocity) {
    element(all + "/velocity");
    s.velocity = series(all + "/velocity/value", f64, {n, d}, kFrameRows);
  }
  element(all + "/species");
  s.species = series(all + "/species/value", i32, {n}, kFrameRows);
  element(all + "/id");
  s.id = series(all + "/id/value", i64, {n}, kFrameRows);

  h5::Object box = h5::create_group(file.id(), all + "/box");
  h5::write_attribute(box.id(), "dimension", l.dim);
  std::vector<std::string> boundary;
  for (int a = 0; a < l.dim; ++a) {
    boundary.push_back(f.container.periodic(a) ? "periodic" : "none");
  }
  h5::write_attribute(box.id(), "boundary", boundary);
  element(all + "/box/edges");
  s.edges = series(all + "/box/edges/value", f64, {d}, kFrameRows);

  s.radius = series(L::kRadius, f64, {n}, kFrameRows);
  if (l.angular_columns) {
    s.angular_velocity = series(L::kAngularVelocity, f64,
                                {n, static_cast<hsize_t>(l.angular_columns)}, kFrameRows);
  }
  s.tap = series(L::kTap, i64, {}, kFrameRows);
  s.cycle = series(L::kCycle, i64, {}, kFrameRows);
  if (l.supports) s.supports = series(L::kSupports, i64, {n, 2}, kFrameRows);

  h5::create_group(file.id(), L::kContainer);
  s.shape = series(L::kShape, shape_type.id(), {}, kFrameRows);
  s.lo = series(L::kLo, f64, {3}, kFrameRows);
  s.hi = series(L::kHi, f64, {3}, kFrameRows);
  s.boundary = series(L::kBoundary, boundary_type.id(), {3, 2}, kFrameRows);
  s.cylinder_radius = series(L::kCylinderRadius, f64, {}, kFrameRows);
  s.cylinder_center = series(L::kCylinderCenter, f64, {2}, kFrameRows);
  s.wall_offset = series(L::kWallOffset, f64, {3}, kFrameRows);
  s.wall_velocity = series(L::kWallVelocity, f64, {3}, kFrameRows);

  if (l.contacts) {
    h5::create_group(file.id(), L::kContacts);
    s.contact_offset = series(L::kContactOffset, i64, {}, kFrameRows);
    s.contact_count = series(L::kContactCount, i64, {}, kFrameRows);
    s.contact_i = series(L::kContactI, i64, {}, kContactRows);
    s.contact_j = series(L::kContactJ, i64, {}, kContactRows);
    s.contact_overlap = series(L::kContactOverlap, f64, {}, kContactRows);
    s.contact_normal = series(L::kContactNormal, f64, {d}, kContactRows);
    s.contact_tangential = series(L::kContactTangential, f64, {d}, kContactRows);
    s.contact_point = series(L::kContactPoint, f64, {d}, kContactRows);
  }
  ds = std::move(s);
}

void FrameWriter::Impl::write(const Frame& f) {
  const Layout& l = *layout;
  const Datasets& s = *ds;
  const hid_t f64 = H5T_NATIVE_DOUBLE, i64 = H5T_NATIVE_INT64, i32 = H5T_NATIVE_INT32;

  // HDF5 stores C order: rows of particles. Eigen keeps coordinates column by column.
  const RowMajor position = f.position;
  s.position.append(f64, position.data());
  if (l.velocity) {
    const RowMajor velocity = *f.velocity;
    s.velocity.append(f64, velocity.data());
  }
  s.species.append(i32, f.species.data());
  s.id.append(i64, f.id.data());
  const Eigen::Vector3d edges = f.container.hi - f.container.lo;
  s.edges.append(f64, edges.data());

  s.radius.append(f64, f.radius.data());
  if (l.angular_columns) {
    const RowMajor angular = *f.angular_velocity;
    s.angular_velocity.append(f64, angular.data());
  }
  s.tap.append(i64, &f.tap);
  s.cycle.append(i64, &f.cycle);
  if (l.supports) {
    Eigen::Array<std::int64_t, Eigen::Dynamic, 2, Eigen::RowMajor> pairs(l.particles, 2);
    pairs.col(0) = f.supports->left;
    pairs.col(1) = f.supports->right;
    s.supports.append(i64, pairs.data());
  }

  const Container& c = f.container;
  const auto shape = static_cast<unsigned char>(c.shape);
  s.shape.append(shape_type.id(), &shape);
  s.lo.append(f64, c.lo.data());
  s.hi.append(f64, c.hi.data());
  unsigned char boundary[3][2];
  for (int a = 0; a < 3; ++a) {
    for (int side = 0; side < 2; ++side) {
      boundary[a][side] = static_cast<unsigned char>(c.boundary[a][side]);
    }
  }
  s.boundary.append(boundary_type.id(), boundary);
  s.cylinder_radius.append(f64, &c.cylinder_radius);
  s.cylinder_center.append(f64, c.cylinder_center.data());
  s.wall_offset.append(f64, c.wall_offset.data());
  s.wall_velocity.append(f64, c.wall_velocity.data());

  if (l.contacts) {
    const Contacts& k = *f.contacts;
    const auto m = static_cast<hsize_t>(k.size());
    s.contact_i.append(i64, k.i.data(), m);
    s.contact_j.append(i64, k.j.data(), m);
    s.contact_overlap.append(f64, k.overlap.data(), m);
    const RowMajor normal = k.normal_force, tangential = k.tangential_force, point = k.point;
    s.contact_normal.append(f64, normal.data(), m);
    s.contact_tangential.append(f64, tangential.data(), m);
    s.contact_point.append(f64, point.data(), m);
    const long long offset = contacts_written, count = static_cast<long long>(m);
    s.contact_offset.append(H5T_NATIVE_LLONG, &offset);
    s.contact_count.append(H5T_NATIVE_LLONG, &count);
    contacts_written += count;
  }

  // The step commits the frame: written last, after everything it stands for.
  s.time.append(f64, &f.time);
  s.step.append(i64, &f.step);
  h5::check(H5Fflush(file.id(), H5F_SCOPE_GLOBAL), "cannot flush (is the disk full?)");
}

FrameWriter::FrameWriter(const std::filesystem::path& path, const std::string& provenance_json)
    : impl_(std::make_unique<Impl>()) {
  h5::silence_error_stack();
  impl_->name = path.string();
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    throw InputError(impl_->name + ": already exists (the frame store never overwrites a file)");
  }
  h5::input_errors_of(impl_->name, [&] { impl_->create_file(provenance_json); });
}

FrameWriter::~FrameWriter() = default;

void FrameWriter::append(const Frame& frame) {
  h5::silence_error_stack();
  Impl& w = *impl_;
  if (w.closed) throw InternalError(w.name + ": frame appended after close()");
  check_sizes(frame, w.name);
  const Layout l = Layout::of(frame);
  if (!w.layout) {
    w.layout = l;
    h5::input_errors_of(w.name, [&] {
      w.create_datasets(frame);
      h5::check(H5Fstart_swmr_write(w.file.id()), "cannot start SWMR writing");
    });
  } else if (!(l == *w.layout)) {
    throw InternalError(w.name + ": frame " + std::to_string(w.frames) + " has " + describe(l) +
                        ", but every frame of one file must match the first (" +
                        describe(*w.layout) + ")");
  }
  h5::input_errors_of(w.name, [&] { w.write(frame); });
  ++w.frames;
}

void FrameWriter::close() {
  h5::silence_error_stack();
  Impl& w = *impl_;
  if (w.closed) return;
  w.closed = true;
  h5::input_errors_of(w.name, [&] {
    w.ds.reset();
    // Closing the file ends SWMR writing; only then may the complete flag be set.
    const hid_t file = w.file.id();
    h5::check(H5Fclose(file), "cannot close the file (is the disk full?)");
    static_cast<void>(w.file.release());
    h5::Object fapl = h5::owned(file_access_latest(), "cannot make the file access list");
    h5::Object reopened = h5::owned(H5Fopen(w.name.c_str(), H5F_ACC_RDWR, fapl.id()),
                                    "cannot reopen the file to mark it complete");
    h5::Object ext = h5::open_group(reopened.id(), L::kExtension);
    h5::write_attribute(ext.id(), L::kCompleteAttr, 1);
    h5::check(H5Fflush(reopened.id(), H5F_SCOPE_GLOBAL), "cannot flush (is the disk full?)");
  });
}

long FrameWriter::frames() const { return impl_->frames; }

}  // namespace granpipe
