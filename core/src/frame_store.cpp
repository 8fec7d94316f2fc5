// FrameWriter: frames.h5 as H5MD 1.1 plus the /granpipe extension (docs/file-format.md).
//
// Crash safety rests on four things: HDF5's SWMR mode (a killed writer leaves a file
// whose flushed state is consistent), paged file space (a killed write never tears a
// metadata block, h5_file.hpp), a fixed write order within a frame (every other dataset
// first, then time, then step), and the reader counting only frames present in every
// dataset. The `complete` attribute is set only by close(), after SWMR has ended.
#include "granpipe/frame_store.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>

#include "granpipe/errors.hpp"
#include "granpipe/version.hpp"
#include "h5_column.hpp"
#include "h5_dataset.hpp"
#include "h5_file.hpp"
#include "h5_frame_layout.hpp"

namespace granpipe {
namespace L = frame_layout;

namespace {

using RowMajor = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The columns of one table as the writer saw them in the first frame: every later frame
// must carry the same.
struct TableLayout {
  std::vector<std::pair<std::string, int>> columns;  // name, components
  static TableLayout of(const PropertyTable& t) {
    TableLayout l;
    for (std::size_t k = 0; k < t.size(); ++k) {
      l.columns.emplace_back(t.column(k).name(), t.column(k).components());
    }
    return l;
  }
  bool operator==(const TableLayout&) const = default;
};

// What every frame of one file carries, fixed by the first frame.
struct Layout {
  Eigen::Index particles = 0;
  int dim = 0;
  TableLayout particle_columns, observables;
  std::optional<TableLayout> contacts;

  static Layout of(const Frame& f) {
    return {f.size(), f.dim, TableLayout::of(f.particles), TableLayout::of(f.observables),
            f.contacts ? std::optional(TableLayout::of(*f.contacts)) : std::nullopt};
  }
  bool operator==(const Layout&) const = default;
};

std::string describe(const TableLayout& t) {
  std::string s;
  for (const auto& [name, components] : t.columns) {
    s += (s.empty() ? "" : " ") + name;
    if (components != 1) s += "[" + std::to_string(components) + "]";
  }
  return s.empty() ? "none" : s;
}

std::string describe(const Layout& l) {
  std::string s = std::to_string(l.particles) + " particles in " + std::to_string(l.dim) +
                  "D (columns: " + describe(l.particle_columns) +
                  "; observables: " + describe(l.observables);
  if (l.contacts) s += "; contacts: " + describe(*l.contacts);
  return s + ")";
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

}  // namespace

struct FrameWriter::Impl {
  struct Series {
    std::string path;
    h5::Object dataset;
    void append(hid_t mem_type, const void* data, hsize_t rows = 1) const {
      h5::append_rows(dataset.id(), path, mem_type, data, rows);
    }
  };
  // A column of the frame and the series it is appended to.
  struct ColumnSeries {
    std::string name;
    Series series;
  };
  // Every dataset of the file, created together when the first frame arrives (SWMR
  // forbids creating objects once it has started).
  struct Datasets {
    Series step, time, edges;
    std::vector<ColumnSeries> particles, observables, contacts;
    Series shape, lo, hi, boundary, cylinder_radius, cylinder_center, wall_offset, wall_velocity;
    Series contact_offset, contact_count;
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
    return {path,
            h5::create_series(file.id(), path, type, item,
                              chunk_rows(item, H5Tget_size(type), max_rows), fill_type, fill)};
  }
  // The series of one column, with the attributes that let it read back as its property.
  Series column_series(const std::string& path, const Column& c, const h5::Shape& front,
                       hsize_t max_rows) {
    h5::Shape item = front;
    for (hsize_t n : h5::item_shape(c)) item.push_back(n);
    Series s = series(path, h5::file_type(c.property().type), item, max_rows);
    h5::write_property_attributes(s.dataset.id(), c.property());
    return s;
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
  void create_particles(const Frame& f, Datasets& s);
  void create_container(Datasets& s);
  void create_contacts(const Frame& f, Datasets& s);
  void write(const Frame& f);
  void write_container(const Container& c);
  void write_contacts(const PropertyTable& contacts);
};

void FrameWriter::Impl::create_file(const std::string& provenance) {
  file = h5::create_swmr_file(name);
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
  h5::check(H5Fflush(file.id(), H5F_SCOPE_GLOBAL), "cannot flush (is the disk full?)");
}

void FrameWriter::Impl::create_particles(const Frame& f, Datasets& s) {
  const auto n = static_cast<hsize_t>(f.size()), d = static_cast<hsize_t>(f.dim);
  const std::string all = L::particles(L::kGroup);
  h5::create_group(file.id(), L::kParticles);
  h5::create_group(file.id(), all);
  h5::create_group(file.id(), all + "/position");
  const long long unwritten = L::kUnwrittenStep;
  s.step =
      series(all + "/position/step", H5T_STD_I64LE, {}, kFrameRows, H5T_NATIVE_LLONG, &unwritten);
  s.time = series(all + "/position/time", H5T_IEEE_F64LE, {}, kFrameRows);
  for (std::size_t k = 0; k < f.particles.size(); ++k) {
    const Column& c = f.particles.column(k);
    const std::string path = all + "/" + c.name();
    if (c.name() != "position") element(path);
    s.particles.push_back({c.name(), column_series(path + "/value", c, {n}, kFrameRows)});
  }

  h5::Object box = h5::create_group(file.id(), all + "/box");
  h5::write_attribute(box.id(), "dimension", f.dim);
  std::vector<std::string> boundary;
  for (int a = 0; a < f.dim; ++a) {
    boundary.push_back(f.container.periodic(a) ? "periodic" : "none");
  }
  h5::write_attribute(box.id(), "boundary", boundary);
  element(all + "/box/edges");
  s.edges = series(all + "/box/edges/value", H5T_IEEE_F64LE, {d}, kFrameRows);

  if (f.observables.size() > 0) h5::create_group(file.id(), L::kObservables);
  for (std::size_t k = 0; k < f.observables.size(); ++k) {
    const Column& c = f.observables.column(k);
    const std::string path = L::kObservables + "/" + c.name();
    element(path);
    s.observables.push_back({c.name(), column_series(path + "/value", c, {}, kFrameRows)});
  }
}

void FrameWriter::Impl::create_container(Datasets& s) {
  const hid_t f64 = H5T_IEEE_F64LE;
  h5::create_group(file.id(), L::kContainer);
  s.shape = series(L::kShape, shape_type.id(), {}, kFrameRows);
  s.lo = series(L::kLo, f64, {3}, kFrameRows);
  s.hi = series(L::kHi, f64, {3}, kFrameRows);
  s.boundary = series(L::kBoundary, boundary_type.id(), {3, 2}, kFrameRows);
  s.cylinder_radius = series(L::kCylinderRadius, f64, {}, kFrameRows);
  s.cylinder_center = series(L::kCylinderCenter, f64, {2}, kFrameRows);
  s.wall_offset = series(L::kWallOffset, f64, {3}, kFrameRows);
  s.wall_velocity = series(L::kWallVelocity, f64, {3}, kFrameRows);
}

void FrameWriter::Impl::create_contacts(const Frame& f, Datasets& s) {
  h5::create_group(file.id(), L::kContacts);
  s.contact_offset = series(L::kContactOffset, H5T_STD_I64LE, {}, kFrameRows);
  s.contact_count = series(L::kContactCount, H5T_STD_I64LE, {}, kFrameRows);
  for (std::size_t k = 0; k < f.contacts->size(); ++k) {
    const Column& c = f.contacts->column(k);
    s.contacts.push_back(
        {c.name(), column_series(L::kContacts + "/" + c.name(), c, {}, kContactRows)});
  }
}

namespace {
// Writes the column order of a table; nothing for an empty one.
void write_order(hid_t group, const std::string& attribute, const PropertyTable& t) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < t.size(); ++k) names.push_back(t.column(k).name());
  if (!names.empty()) h5::write_attribute(group, attribute, names);
}
}  // namespace

void FrameWriter::Impl::create_datasets(const Frame& f) {
  h5::Object ext = h5::open_group(file.id(), L::kExtension);
  write_order(ext.id(), L::kParticleColumnsAttr, f.particles);
  write_order(ext.id(), L::kObservablesAttr, f.observables);
  if (f.contacts) write_order(ext.id(), L::kContactColumnsAttr, *f.contacts);
  Datasets s;
  create_particles(f, s);
  create_container(s);
  if (f.contacts) create_contacts(f, s);
  ds = std::move(s);
}

void FrameWriter::Impl::write_container(const Container& c) {
  const Datasets& s = *ds;
  const hid_t f64 = H5T_NATIVE_DOUBLE;
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
}

void FrameWriter::Impl::write_contacts(const PropertyTable& contacts) {
  const Datasets& s = *ds;
  const auto m = static_cast<hsize_t>(contacts.rows());
  for (const ColumnSeries& c : s.contacts) {
    h5::append_column(c.series.dataset.id(), c.series.path, *contacts.find(c.name), m);
  }
  const long long offset = contacts_written, count = static_cast<long long>(m);
  s.contact_offset.append(H5T_NATIVE_LLONG, &offset);
  s.contact_count.append(H5T_NATIVE_LLONG, &count);
  contacts_written += count;
}

void FrameWriter::Impl::write(const Frame& f) {
  const Datasets& s = *ds;
  for (const ColumnSeries& c : s.particles) {
    h5::append_column(c.series.dataset.id(), c.series.path, *f.particles.find(c.name), 1);
  }
  for (const ColumnSeries& c : s.observables) {
    h5::append_column(c.series.dataset.id(), c.series.path, *f.observables.find(c.name), 1);
  }
  const Eigen::Vector3d edges = f.container.hi - f.container.lo;
  s.edges.append(H5T_NATIVE_DOUBLE, edges.data());
  write_container(f.container);
  if (f.contacts) write_contacts(*f.contacts);

  // The step commits the frame: written last, after everything it stands for.
  s.time.append(H5T_NATIVE_DOUBLE, &f.time);
  s.step.append(H5T_NATIVE_INT64, &f.step);
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
  frame.check_layout(w.name);
  const Layout l = Layout::of(frame);
  if (!w.layout) {
    w.layout = l;
    h5::input_errors_of(w.name, [&] {
      w.create_datasets(frame);
      h5::check(H5Fstart_swmr_write(w.file.id()), "cannot start SWMR writing (is the disk full?)");
    });
  } else if (l.particles != w.layout->particles) {
    // An input's count may change (a dump of a pouring run); frames.h5 holds one.
    std::ostringstream s;
    s << w.name << ": frame " << w.frames << " (step " << frame.step << ") has " << l.particles
      << " particles, the first frame " << w.layout->particles
      << ": expected one particle count in a frames file (with output.save_frames false, "
         "frames whose count changes are analysed unsaved)";
    throw InputError(s.str());
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
    const h5::Object fapl = h5::latest_format_access();
    h5::Object reopened = h5::owned(H5Fopen(w.name.c_str(), H5F_ACC_RDWR, fapl.id()),
                                    "cannot reopen the file to mark it complete");
    h5::Object ext = h5::open_group(reopened.id(), L::kExtension);
    h5::write_attribute(ext.id(), L::kCompleteAttr, 1);
    h5::check(H5Fflush(reopened.id(), H5F_SCOPE_GLOBAL), "cannot flush (is the disk full?)");
  });
}

long FrameWriter::frames() const { return impl_->frames; }

}  // namespace granpipe
