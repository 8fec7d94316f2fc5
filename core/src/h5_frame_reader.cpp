// FrameReader: frames from any H5MD file. granpipe's own files (with the /granpipe
// extension, docs/file-format.md) read back bit for bit; other tools' files give
// positions and whatever standard elements they hold, with radii set to a default and
// the container made from the H5MD box.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <unordered_map>

#include "granpipe/available_memory.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/file_kind.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/frame_store.hpp"
#include "granpipe/text_words.hpp"
#include "h5_column.hpp"
#include "h5_dataset.hpp"
#include "h5_element.hpp"
#include "h5_frame_layout.hpp"
#include "length_unit.hpp"

namespace granpipe {
namespace L = frame_layout;

namespace {

// Whether the file's superblock (version 2 or later, at the file's start) still carries the
// "open for writing" flag (bit 0 of byte 11) that its writer clears on closing: HDF5 refuses
// such a file, and a run killed hard leaves its frames.partial.h5 so.
bool marked_open_for_writing(const std::string& name) {
  std::ifstream in(name, std::ios::binary);
  std::array<unsigned char, 12> head{};
  if (!in.read(reinterpret_cast<char*>(head.data()), head.size())) return false;
  return head[8] >= 2 && (head[11] & 0x1u) != 0;
}

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

// A SWMR reader re-reads metadata whose checksum fails (a live writer may be half-way
// through flushing it), sleeping between attempts for twice as long each time, from 1 ns.
// HDF5's default of 100 attempts makes a file with one damaged checksum hang for good;
// 20 attempts wait about a millisecond in all.
constexpr unsigned kSwmrReadAttempts = 20;

h5::Object swmr_read_access() {
  h5::Object fapl = h5::owned(H5Pcreate(H5P_FILE_ACCESS), "cannot make the file access list");
  h5::check(H5Pset_metadata_read_attempts(fapl.id(), kSwmrReadAttempts),
            "cannot set the metadata read attempts");
  return fapl;
}

// Opens normally, else as a SWMR reader: a file whose writer was killed (or is still
// running) refuses a normal open but reads back every frame it flushed.
h5::Object open_file(const std::string& name, bool& swmr) {
  // Opening a FIFO without a writer waits for one: `granpipe inspect` hung.
  if (!regular_file_at(name)) {
    const std::string found = what_is_at(name);
    throw InputError(name + (found == "no such file" ? ": no such file"
                                                     : ": expected an HDF5 file, got " + found));
  }
  if (!std::ifstream(name).good()) throw InputError(name + ": cannot be read (permissions?)");
  if (H5Fis_hdf5(name.c_str()) <= 0) {
    throw InputError(name + ": not an HDF5 file (no HDF5 signature)");
  }
  swmr = false;
  hid_t id = H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) {
    swmr = true;
    const h5::Object fapl = swmr_read_access();
    id = H5Fopen(name.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, fapl.id());
  }
  if (id < 0 && marked_open_for_writing(name)) {
    throw InputError(name +
                     ": expected an HDF5 file its writer closed, found one still marked "
                     "open for writing (a run killed before it closed the file, or one "
                     "writing it now); if none writes it, `h5clear -s " +
                     name + "` clears the mark and its frames can be read");
  }
  if (id < 0) throw InputError(name + ": not a readable HDF5 file (truncated or corrupt)");
  return h5::Object(id);
}

// A particle column or observable stored as an H5MD element.
struct ElementColumn {
  Property property;
  h5::Element element;
};

// A contact column: rows of every frame concatenated.
struct ContactColumn {
  Property property;
  std::string path;
  h5::Object dataset;
};

// The container datasets of a granpipe file, row k for frame k.
struct ContainerSeries {
  h5::Object shape, lo, hi, boundary, cylinder_radius, cylinder_center, wall_offset, wall_velocity;
};

// Puts columns in the order the writer's frames held them (`attribute` of the extension
// group lists their names); columns it does not list keep their place after those. A
// listed column missing from `base` (position aside, read on its own) is refused: a file
// without its radii read them as the default and blamed particle 0 for a radius of 0.
template <class C>
void restore_order(hid_t file, const std::string& attribute, const std::string& base,
                   std::vector<C>& columns) {
  h5::Object group = h5::open_group(file, L::kExtension);
  if (!h5::has_attribute(group.id(), attribute)) return;
  const auto order = h5::read_string_attribute(group.id(), L::kExtension, attribute);
  for (const std::string& name : order) {
    const bool found =
        name == "position" || std::any_of(columns.begin(), columns.end(),
                                          [&](const C& c) { return c.property.name == name; });
    if (!found) {
      throw h5::Error(base + "/" + name + ": missing, where " + L::kExtension + "@" + attribute +
                      " lists it (a damaged granpipe file?)");
    }
  }
  auto rank = [&](const C& c) {
    return std::find(order.begin(), order.end(), c.property.name) - order.begin();
  };
  std::stable_sort(columns.begin(), columns.end(),
                   [&](const C& a, const C& b) { return rank(a) < rank(b); });
}

// Frame k of an element into a column: one row of a time-dependent element, or the
// whole of a time-independent one.
void read_element(const h5::Element& e, long k, Column& c) {
  if (e.timed()) {
    h5::read_column(e.dataset(), e.path(), e.row(k), 1, c);
  } else {
    h5::read_column(e.dataset(), e.path(), 0, static_cast<hsize_t>(c.rows()), c);
  }
}

// Each particle once: two rows of one id would read as one particle in every analysis that
// follows particles by their ids, and as two in every count.
void check_unique_ids(const Frame& f, const std::string& dataset, long k) {
  const IndexArray& id = f.id();
  // Most files number their particles in order: unique without a table of them.
  if (std::adjacent_find(id.begin(), id.end(), std::greater_equal<>()) == id.end()) return;
  std::unordered_map<std::int64_t, Eigen::Index> first_row;
  first_row.reserve(static_cast<std::size_t>(id.size()));
  for (Eigen::Index i = 0; i < id.size(); ++i) {
    const auto [seen, fresh] = first_row.emplace(id[i], i);
    if (fresh) continue;
    throw h5::Error(dataset + ": frame " + std::to_string(k) +
                    ": expected each particle id once, got id " + std::to_string(id[i]) +
                    " again (particles " + std::to_string(seen->second) + " and " +
                    std::to_string(i) + ")");
  }
}

// Bytes of each stored value when it is a float (8: doubles; 4: the 32-bit floats other
// tools write), 8 for integer storage, which holds its values exactly.
int float_bytes(const h5::Element& e) {
  const h5::Object type =
      h5::owned(H5Dget_type(e.dataset()), e.path() + ": cannot read the data type");
  if (H5Tget_class(type.id()) != H5T_FLOAT) return 8;
  return static_cast<int>(H5Tget_size(type.id()));
}

}  // namespace

bool FrameFileInfo::has(std::string_view column) const {
  return std::any_of(columns.begin(), columns.end(),
                     [&](const Property& p) { return p.name == column; });
}

namespace {
// A compressed file may declare far more than it stores (4e8 particles in 9 MB): what it
// declares is refused, naming the dataset, where it would not fit in memory (it ran out of
// memory reading it, a line naming no file).
void check_fits(const std::string& path, double bytes, const std::string& what) {
  const double available = available_memory();
  if (std::isnan(available) || bytes <= available) return;
  constexpr double kGB = 1e9;
  throw h5::Error(path + ": " + what + ": " + format_number(bytes / kGB, 3) +
                  " GB needed, this machine (or the process's memory limit) has " +
                  format_number(available / kGB, 3) + " GB available");
}
}  // namespace

struct FrameReader::Impl {
  std::string name;
  h5::Object file;
  FrameFileInfo info;
  double default_radius = 0.5;
  bool ours = false;  // written by granpipe: every element on position's clock
  std::optional<h5::Element> position, edges;
  std::vector<ElementColumn> columns, observables;
  std::vector<std::int64_t> steps;
  std::vector<double> times;
  std::array<bool, 3> periodic{};
  // Along walled axes of another tool's box: walls at [-L/2, L/2] (else [0, L]), as the
  // file's centres decide (place_walls_of_file), and which placements they allow.
  std::array<bool, 3> centred{};
  FrameReader::WallPlacements allowed;
  std::optional<ContainerSeries> container_series;
  std::vector<ContactColumn> contact_columns;
  std::vector<std::int64_t> contact_offset, contact_count;

  void open(const std::string& group);
  std::string choose_group(const std::string& group) const;
  void check_version();
  void check_h5md_version();
  void open_position(const std::string& base);
  void open_columns(const std::string& base);
  std::optional<ElementColumn> open_column(const std::string& base, const std::string& name);
  void open_observables();
  void open_box(const std::string& base);
  void check_length_units() const;
  void check_frame_fits() const;
  hsize_t rows(const std::string& path, const h5::Shape& item, h5::Object& out);
  void open_container(hsize_t& frames);
  hsize_t open_contacts(hsize_t& frames);
  void settle_frames();
  void check_clocks() const;
  void check_steps_written() const;
  void keep_frames_held(hsize_t& frames, hsize_t rows, const std::string& path) const;
  void check_contacts_in_order(hsize_t frames, hsize_t contact_rows) const;
  void map_foreign_elements();
  Frame read_particles(long k) const;
  Frame read(long k) const;
  std::vector<double> edge_lengths(long k) const;
  void check_edges_agree(long k, const Container& c) const;
  Container box_container(long k, const Frame& f) const;
  void place_walls_of_file();
  void place_walls(Container& c, int axis, const Frame& f, long k) const;
  [[noreturn]] void refuse_outside(const Frame& f, int axis, double length, long k,
                                   const std::string& placed) const;
  Container container_at(long k) const;
  void read_contacts(long k, Frame& f) const;
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

// The H5MD layer's own version, where a file states it: this reader knows 1.x, and a file
// of another major version may lay its elements out otherwise.
void FrameReader::Impl::check_h5md_version() {
  if (!h5::is_group(file.id(), "/h5md")) return;
  h5::Object h5md = h5::open_group(file.id(), "/h5md");
  if (!h5::has_attribute(h5md.id(), "version")) return;
  const auto version = h5::read_integer_attribute(h5md.id(), "/h5md", "version");
  if (!version.empty() && version[0] == 1) return;
  std::string found = version.empty() ? "none" : std::to_string(version[0]);
  if (version.size() > 1) {
    found += '.';  // "." + to_string(...) gave GCC 12 a false -Wrestrict
    found += std::to_string(version[1]);
  }
  throw h5::Error("/h5md@version: expected H5MD 1.x, got " + found);
}

void FrameReader::Impl::check_version() {
  h5::Object group = h5::open_group(file.id(), L::kExtension);
  const auto version = h5::read_integer_attribute(group.id(), L::kExtension, L::kVersionAttr);
  if (version.empty() || version[0] != L::kVersionMajor) {
    const std::string found = version.empty() ? "no version" : std::to_string(version[0]) + ".x";
    throw h5::Error(L::kExtension + "@version: expected frames layout " +
                    std::to_string(L::kVersionMajor) + ".x, got " + found +
                    " (written by another granpipe version; docs/file-format.md lists the "
                    "layouts)");
  }
  info.granpipe_file = true;
  if (h5::has_attribute(group.id(), L::kCompleteAttr)) {
    const auto flag = h5::read_integer_attribute(group.id(), L::kExtension, L::kCompleteAttr);
    // Any other value is damage: read as "unfinished", it would let a damaged file's
    // short elements cut frames off with a warning meant for a killed writer.
    if (flag.size() != 1 || (flag[0] != 0 && flag[0] != 1)) {
      throw h5::Error(
          L::kExtension + "@" + L::kCompleteAttr +
          ": expected 0 (the writer never finished) or 1, got " +
          (flag.size() == 1 ? std::to_string(flag[0]) : std::to_string(flag.size()) + " values") +
          " (damaged file)");
    }
    info.complete = info.complete && flag[0] == 1;
  } else {
    info.complete = false;
  }
}

void FrameReader::Impl::open_position(const std::string& base) {
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
  info.position_bytes = float_bytes(*position);
  // A step and a time per frame are read now.
  check_fits(position->path(), static_cast<double>(info.frames) * 16.0,
             std::to_string(info.frames) + " frames' steps and times");
  if (position->timed()) {
    steps = position->steps();
    times = position->times();
  } else {
    steps = {0};
  }
}

std::optional<ElementColumn> FrameReader::Impl::open_column(const std::string& base,
                                                            const std::string& column) {
  const Property* standard = find_standard(column, Scope::Particle);
  // Other tools' own elements (image, charge, ...) are theirs to interpret.
  if (!ours && !standard) return std::nullopt;
  std::optional<h5::Element> e = h5::Element::open(file.id(), base + "/" + column);
  if (!e) return std::nullopt;
  const h5::Shape item = e->item();
  const auto n = static_cast<hsize_t>(info.particles);
  if (item.empty() || item[0] != n) {
    throw h5::Error(e->path() + ": expected " + std::to_string(n) +
                    " rows (one per particle) per frame, got " + h5::format_shape(item));
  }
  const h5::Shape rest(item.begin() + 1, item.end());
  Property p = h5::read_property(e->dataset(), e->path(), column, Scope::Particle, rest, info.dim);
  const int c = p.components_in(info.dim);
  const h5::Shape expected = p.components == 1 ? h5::Shape{} : h5::Shape{static_cast<hsize_t>(c)};
  if (rest != expected) {
    throw h5::Error(e->path() + ": expected " + h5::format_shape(h5::Shape{n}) +
                    (expected.empty() ? "" : " x " + h5::format_shape(expected)) +
                    " per frame, got " + h5::format_shape(item));
  }
  if (column == "radius") info.radius_bytes = float_bytes(*e);
  return ElementColumn{std::move(p), std::move(*e)};
}

void FrameReader::Impl::open_columns(const std::string& base) {
  h5::Object group = h5::open_group(file.id(), base);
  for (const std::string& column : h5::members(group.id(), base)) {
    if (column == "position" || column == "box") continue;
    if (auto c = open_column(base, column)) columns.push_back(std::move(*c));
  }
}

void FrameReader::Impl::open_observables() {
  if (!h5::is_group(file.id(), L::kObservables)) return;
  h5::Object group = h5::open_group(file.id(), L::kObservables);
  for (const std::string& o : h5::members(group.id(), L::kObservables)) {
    std::optional<h5::Element> e = h5::Element::open(file.id(), L::kObservables + "/" + o);
    if (!e) continue;
    const h5::Shape item = e->item();
    Property p = h5::read_property(e->dataset(), e->path(), o, Scope::Frame, item, info.dim);
    observables.push_back({std::move(p), std::move(*e)});
  }
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

hsize_t FrameReader::Impl::rows(const std::string& path, const h5::Shape& item, h5::Object& out) {
  out = h5::open_stored_dataset(file.id(), path);
  return rows_of(h5::shape_of(out.id(), path), item, path);
}

void FrameReader::Impl::open_container(hsize_t& frames) {
  ContainerSeries x;
  auto series = [&](const std::string& path, const h5::Shape& item, h5::Object& out) {
    keep_frames_held(frames, rows(path, item, out), path);
  };
  series(L::kShape, {}, x.shape);
  series(L::kLo, {3}, x.lo);
  series(L::kHi, {3}, x.hi);
  series(L::kBoundary, {3, 2}, x.boundary);
  series(L::kCylinderRadius, {}, x.cylinder_radius);
  series(L::kCylinderCenter, {2}, x.cylinder_center);
  series(L::kWallOffset, {3}, x.wall_offset);
  series(L::kWallVelocity, {3}, x.wall_velocity);
  container_series = std::move(x);
}

// The contact columns and the frames' offsets into them; returns the contact rows that
// every column holds.
hsize_t FrameReader::Impl::open_contacts(hsize_t& frames) {
  h5::Object offset, count;
  keep_frames_held(frames, rows(L::kContactOffset, {}, offset), L::kContactOffset);
  keep_frames_held(frames, rows(L::kContactCount, {}, count), L::kContactCount);
  contact_offset = h5::read_integer_rows(offset.id(), L::kContactOffset, 0, frames);
  contact_count = h5::read_integer_rows(count.id(), L::kContactCount, 0, frames);
  h5::Object group = h5::open_group(file.id(), L::kContacts);
  hsize_t contact_rows = std::numeric_limits<hsize_t>::max();
  for (const std::string& column : h5::members(group.id(), L::kContacts)) {
    if (column == "offset" || column == "count") continue;
    ContactColumn c{{}, L::kContacts + "/" + column, {}};
    c.dataset = h5::open_stored_dataset(file.id(), c.path);
    const h5::Shape shape = h5::shape_of(c.dataset.id(), c.path);
    const h5::Shape item = shape.empty() ? shape : h5::Shape(shape.begin() + 1, shape.end());
    c.property = h5::read_property(c.dataset.id(), c.path, column, Scope::Contact, item, info.dim);
    const int k = c.property.components_in(info.dim);
    const h5::Shape expected =
        c.property.components == 1 ? h5::Shape{} : h5::Shape{static_cast<hsize_t>(k)};
    contact_rows = std::min(contact_rows, rows_of(shape, expected, c.path));
    contact_columns.push_back(std::move(c));
  }
  restore_order(file.id(), L::kContactColumnsAttr, L::kContacts, contact_columns);
  if (contact_columns.size() < 2 || contact_columns[0].property.name != "i" ||
      contact_columns[1].property.name != "j") {
    throw h5::Error(L::kContacts + ": expected the contact columns i and j");
  }
  return contact_rows;
}

// A granpipe file: frame k is row k of everything, but a killed writer may leave some
// datasets a frame ahead of others, and rows it extended but never committed.
// A file no writer holds open has one step and one time for every sample: a clock of
// another length would read as fewer frames, without a word. granpipe's own elements share
// the positions' clock (hard links): theirs is the positions'.
void FrameReader::Impl::check_clocks() const {
  auto check = [](const h5::Element& e) {
    const auto clock = e.mismatched_clock();
    if (!clock) return;
    throw h5::Error(clock->path + ": expected a row for each of the " +
                    std::to_string(e.value_rows()) + " samples of " + e.path() + ", got " +
                    std::to_string(clock->rows) + " (damaged file)");
  };
  check(*position);
  if (ours) return;
  if (edges) check(*edges);
  for (const ElementColumn& c : columns) check(c.element);
  for (const ElementColumn& o : observables) check(o.element);
}

// granpipe writes every element of a frame before it marks the file complete: there, a
// frame whose step was never written or an element short of the positions is damage that
// would read as fewer frames, without a word. A killed writer's file keeps the frames
// every element holds.
void FrameReader::Impl::check_steps_written() const {
  for (std::size_t k = 0; k < static_cast<std::size_t>(info.frames); ++k) {
    if (steps[k] != L::kUnwrittenStep) continue;
    throw h5::Error(position->path() + ": frame " + std::to_string(k) +
                    ": expected the step of a written frame in a complete file, got none "
                    "(damaged file)");
  }
}

void FrameReader::Impl::keep_frames_held(hsize_t& frames, hsize_t rows,
                                         const std::string& path) const {
  if (info.complete && rows != static_cast<hsize_t>(info.frames)) {
    throw h5::Error(path + ": expected the " + std::to_string(info.frames) +
                    " frames of the positions in a complete file, got " + std::to_string(rows) +
                    " (damaged file)");
  }
  frames = std::min(frames, rows);
}

void FrameReader::Impl::settle_frames() {
  if (info.complete) {
    check_clocks();
    check_steps_written();
  }
  auto frames = static_cast<hsize_t>(info.frames);
  for (ElementColumn& c : columns) {
    keep_frames_held(frames, c.element.samples(), c.element.path());
    c.element.map_identity();
  }
  for (ElementColumn& o : observables) {
    keep_frames_held(frames, o.element.samples(), o.element.path());
    o.element.map_identity();
  }
  if (edges) {
    keep_frames_held(frames, edges->samples(), edges->path());
    edges->map_identity();
  }
  open_container(frames);
  const bool contacts = h5::is_group(file.id(), L::kContacts);
  const hsize_t contact_rows = contacts ? open_contacts(frames) : 0;
  while (frames > 0 && steps[frames - 1] == L::kUnwrittenStep) --frames;
  // A killed writer may not have written its last frames' contacts; anywhere else, contacts
  // outside the arrays are damage (and a count to allocate from).
  auto within = [&](hsize_t k) {
    const std::int64_t offset = contact_offset[k], count = contact_count[k];
    const auto rows = static_cast<std::int64_t>(contact_rows);
    return offset >= 0 && count >= 0 && count <= rows && offset <= rows - count;
  };
  while (contacts && !info.complete && frames > 0 && !within(frames - 1)) --frames;
  for (hsize_t k = 0; contacts && k < frames; ++k) {
    if (within(k)) continue;
    throw h5::Error(L::kContacts + ": frame " + std::to_string(k) + ": expected rows within the " +
                    std::to_string(contact_rows) + " contact rows, got offset " +
                    std::to_string(contact_offset[k]) + " and count " +
                    std::to_string(contact_count[k]) + " (damaged file)");
  }
  if (contacts && info.complete) check_contacts_in_order(frames, contact_rows);
  info.frames = static_cast<long>(frames);
  info.has_contacts = contacts;
}

// granpipe appends each frame's contacts after the frame before's: in a complete file an
// offset pointing at other rows would read another frame's contacts as this one's, and a
// count cut short would drop some, both without a word.
void FrameReader::Impl::check_contacts_in_order(hsize_t frames, hsize_t contact_rows) const {
  std::int64_t next = 0;
  for (hsize_t k = 0; k < frames; ++k) {
    if (contact_offset[k] != next) {
      throw h5::Error(L::kContactOffset + ": frame " + std::to_string(k) + ": expected offset " +
                      std::to_string(next) + " (after the rows of the frames before), got " +
                      std::to_string(contact_offset[k]) + " (damaged file)");
    }
    next += contact_count[k];
  }
  if (static_cast<hsize_t>(next) == contact_rows) return;
  throw h5::Error(L::kContactCount + ": expected counts summing to the " +
                  std::to_string(contact_rows) + " contact rows of a complete file, got " +
                  std::to_string(next) + " (damaged file)");
}

void FrameReader::Impl::map_foreign_elements() {
  // Other tools may sample elements on their own clocks; an optional element counts
  // only when it has a sample at every frame's step.
  const std::vector<std::int64_t> frame_steps(steps.begin(), steps.begin() + info.frames);
  std::erase_if(columns, [&](ElementColumn& c) {
    if (c.element.map_by_step(frame_steps)) return false;
    // Sizes and identities are no option: left out, the default radius, ids by row and
    // species 0 stood for the file's, exit 0.
    const std::string& name = c.property.name;
    if (name == "radius" || name == "id" || name == "species") {
      throw h5::Error(c.element.path() + ": expected " + (name == "id" ? "an " : "a ") + name +
                      " at every step of the positions, got one on a clock of its own that "
                      "misses some");
    }
    return true;
  });
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
  check_h5md_version();
  const bool extension = h5::is_group(file.id(), L::kExtension);
  if (extension) {
    check_version();
    const h5::Object ext = h5::open_group(file.id(), L::kExtension);
    if (h5::has_attribute(ext.id(), L::kProvenanceAttr)) {
      const auto text = h5::read_string_attribute(ext.id(), L::kExtension, L::kProvenanceAttr);
      if (!text.empty()) info.provenance = text[0];
    }
  }
  if (extension && !h5::is_group(file.id(), L::kParticles) && group.empty()) {
    return;  // a granpipe file closed before its first frame
  }
  if (!h5::is_group(file.id(), L::kParticles)) {
    throw h5::Error(L::kParticles + ": missing (not an H5MD file with particles)");
  }
  info.group = choose_group(group);
  ours = extension && info.group == L::kGroup;
  const std::string base = L::particles(info.group);
  open_position(base);
  open_box(base);
  open_columns(base);
  check_length_units();
  check_frame_fits();
  if (ours) {
    open_observables();
    settle_frames();
    restore_order(file.id(), L::kParticleColumnsAttr, base, columns);
    restore_order(file.id(), L::kObservablesAttr, L::kObservables, observables);
  } else {
    if (info.complete) check_clocks();
    map_foreign_elements();
    place_walls_of_file();
  }
  for (const ElementColumn& c : columns) info.columns.push_back(c.property);
  for (const ElementColumn& o : observables) info.observables.push_back(o.property);
  for (const ContactColumn& c : contact_columns) info.contact_columns.push_back(c.property);
}

// One frame of every column read, as reading holds it: the frame's radius, id and species
// whether the file has them or not, and each column of several components twice (read in
// the file's row order, then copied into the frame's): counting the file's columns alone,
// a frame of 10^7 particles passed the check and ran out of memory naming no file.
void FrameReader::Impl::check_frame_fits() const {
  const auto bytes = [&](int components) { return 8.0 * components * (components > 1 ? 2 : 1); };
  double per_particle = bytes(info.dim) + 8.0 + 8.0 + 4.0;
  for (const ElementColumn& c : columns) {
    const std::string& n = c.property.name;
    if (n != "radius" && n != "id" && n != "species")  // counted above
      per_particle += bytes(c.property.components_in(info.dim));
  }
  check_fits(position->path(), static_cast<double>(info.particles) * per_particle,
             "a frame of " + std::to_string(info.particles) + " particles (" +
                 format_number(per_particle) + " bytes each)");
}

// H5MD states a unit per element, and granpipe computes with the numbers as stored:
// positions in nm beside box edges in angstrom gave a packing fraction 1000 times off with
// exit 0. The lengths the frame is built from must state one unit (however written: A and
// Angstrom, 0.1 nm), or none.
void FrameReader::Impl::check_length_units() const {
  std::string unit, stated_by;
  const auto consider = [&](const h5::Element& e) {
    if (!h5::has_attribute(e.dataset(), "unit")) return;
    const std::vector<std::string> units = h5::read_string_attribute(e.dataset(), e.path(), "unit");
    if (units.size() != 1) {
      throw h5::Error(e.path() + "@unit: expected one unit, got " + std::to_string(units.size()) +
                      " strings");
    }
    const std::string& u = units[0];
    if (u.empty()) return;  // stated as none: read in the others' unit
    if (stated_by.empty()) {
      unit = u;
      stated_by = e.path();
    } else if (!same_length_unit(u, unit)) {
      throw h5::Error(e.path() + "@unit: expected " + granpipe::quoted(unit) + ", the unit of " +
                      stated_by + " (granpipe reads lengths as stored, in one unit), got " +
                      granpipe::quoted(u));
    }
  };
  consider(*position);
  if (edges) consider(*edges);
  for (const ElementColumn& c : columns)
    if (c.property.name == "radius") consider(c.element);
}

// H5MD stores a box's edge lengths but not its origin. Periodic sides need none (positions
// are wrapped where used); walls do: they go at [0, L] or, as some codes centre their
// boxes, [-L/2, L/2], whichever holds every particle centre of the file's frames ([0, L]
// where both do), the same in every frame: placed frame by frame, the walls of one file
// jumped by L/2 between two frames. Centres outside are refused rather than measured
// against walls in the wrong place.
namespace {
// Which placements along `a` hold frame k's centres (edge `length`).
struct Placements {
  bool at_zero = true, centred = true;
};

Placements placements(const Frame& f, int a, double length, const std::string& file, long k) {
  // The frame check names the particle, where min and max of a NaN depend on its place.
  if (!f.position().col(a).allFinite()) f.check(file + ": frame " + std::to_string(k));
  const double lo = f.position().col(a).minCoeff(), hi = f.position().col(a).maxCoeff();
  return {lo >= 0.0 && hi <= length, lo >= -0.5 * length && hi <= 0.5 * length};
}
}  // namespace

// Frame 0 decides each walled axis it fits one way only; where it fits both (centres in
// [0, L/2]: a centred box's grains poured into its upper half), the next frames do, each
// axis until one placement is left: a later frame narrowed an axis frame 0 had decided,
// and frame 0 was refused. Frames are read only while an axis is undecided, and one whose
// centres are not all numbers ends it (refused when it is read, not when the file opens).
void FrameReader::Impl::place_walls_of_file() {
  if (ours || !edges || info.frames == 0 || info.particles == 0) return;
  std::array<Placements, 3> fit;
  const auto undecided = [&](int a) { return !periodic[a] && fit[a].at_zero && fit[a].centred; };
  for (long k = 0; k < info.frames; ++k) {
    bool open = false;
    for (int a = 0; a < info.dim; ++a) open = open || undecided(a);
    if (!open) break;
    const Frame f = read_particles(k);
    if (k > 0 && !f.position().allFinite()) break;
    const std::vector<double> length = edge_lengths(k);
    for (int a = 0; a < info.dim; ++a) {
      if (!undecided(a)) continue;
      const Placements p = placements(f, a, length[a], name, k);
      if (k == 0 && !p.at_zero && !p.centred) refuse_outside(f, a, length[a], k, "");
      fit[a] = {p.at_zero, p.centred};
    }
  }
  for (int a = 0; a < info.dim; ++a) {
    centred[a] = !fit[a].at_zero && fit[a].centred;
    allowed.at_zero[a] = fit[a].at_zero;
    allowed.centred[a] = fit[a].centred;
  }
}

void FrameReader::Impl::place_walls(Container& c, int a, const Frame& f, long k) const {
  const double length = c.hi[a];
  c.lo[a] = centred[a] ? -0.5 * length : 0.0;
  c.hi[a] = c.lo[a] + length;
  const Placements p = placements(f, a, length, name, k);
  if (centred[a] ? p.centred : p.at_zero) return;
  refuse_outside(f, a, length, k,
                 p.at_zero || p.centred ? (centred[a] ? "[-L/2, L/2]" : "[0, L]") : "");
}

// `placed`: where the file's walls are, for centres that fit the other placement only.
void FrameReader::Impl::refuse_outside(const Frame& f, int a, double length, long k,
                                       const std::string& placed) const {
  const double lo = f.position().col(a).minCoeff(), hi = f.position().col(a).maxCoeff();
  const std::string at = edges->path() + ": frame " + std::to_string(k) +
                         ": expected particle centres inside a box of edge " +
                         format_number(length) + " along " + "xyz"[a];
  if (!placed.empty()) {
    const double bottom = placed == "[0, L]" ? 0.0 : -0.5 * length;
    throw h5::Error(at + " at " + placed + ", where the file's frames put its walls, got " +
                    format_apart(lo, bottom) + " to " + format_apart(hi, bottom + length) +
                    " (H5MD stores no origin: walls that move by L/2 between frames are "
                    "refused)");
  }
  // Digits enough to tell the centres from the nearer placement's bounds.
  const double bottom = lo < 0.0 ? -0.5 * length : 0.0, top = lo < 0.0 ? 0.5 * length : length;
  throw h5::Error(at + " (at [0, L] or [-L/2, L/2]), got " + format_apart(lo, bottom) + " to " +
                  format_apart(hi, top));
}

std::vector<double> FrameReader::Impl::edge_lengths(long k) const {
  const int d = info.dim;
  std::vector<double> e(edges->item().size() == 2 ? d * d : d);
  edges->read(k, e.data());
  if (e.size() == static_cast<std::size_t>(d)) return e;
  std::vector<double> length(d);
  for (int a = 0; a < d; ++a) {
    for (int b = 0; b < d; ++b) {
      if (a != b && e[a * d + b] != 0.0) {
        throw h5::Error(edges->path() + ": triclinic boxes are not supported (frame " +
                        std::to_string(k) + ")");
      }
    }
    length[a] = e[a * d + a];
  }
  return length;
}

// granpipe reads its own container, other tools the H5MD box: a file where the two differ
// (one of them edited) would give the same frame two packing fractions. The writer stores
// hi - lo as the edges; a relative 1e-9 allows for a tool that rewrote them rounded.
void FrameReader::Impl::check_edges_agree(long k, const Container& c) const {
  const std::vector<double> length = edge_lengths(k);
  for (int a = 0; a < info.dim; ++a) {
    const double expected = c.hi[a] - c.lo[a], got = length[a];
    const bool same =
        expected == got || (std::isnan(expected) && std::isnan(got)) ||
        std::abs(expected - got) <= 1e-9 * std::max(std::abs(expected), std::abs(got));
    if (same) continue;
    throw h5::Error(edges->path() + ": frame " + std::to_string(k) +
                    ": expected the container's edge along " + "xyz"[a] + " (" + L::kContainer +
                    " hi - lo), " + format_number(expected, 12) + ", got " +
                    format_number(got, 12));
  }
}

Container FrameReader::Impl::box_container(long k, const Frame& f) const {
  Container c;
  const int d = info.dim;
  if (!edges) {
    // A box with every side "none" and no edges: open on all sides, spanning the particles.
    for (int a = 0; a < d; ++a) {
      c.boundary[a] = {Boundary::Open, Boundary::Open};
      if (f.size() > 0) {
        c.lo[a] = (f.position().col(a) - f.radius()).minCoeff();
        c.hi[a] = (f.position().col(a) + f.radius()).maxCoeff();
      }
    }
    return c;
  }
  const std::vector<double> length = edge_lengths(k);
  c.lo.setZero();
  for (int a = 0; a < d; ++a) {
    c.hi[a] = length[a];
    const Boundary b = periodic[a] ? Boundary::Periodic : Boundary::Wall;
    c.boundary[a] = {b, b};
    if (!periodic[a] && f.size() > 0) place_walls(c, a, f, k);
  }
  return c;
}

Container FrameReader::Impl::container_at(long k) const {
  const ContainerSeries& x = *container_series;
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

// Every contact joins a particle to another particle or to a wall (frame.hpp's partner
// codes): an index out of range would otherwise pass as a wall, and the pair drop out of
// every count.
namespace {
void check_partners(const Frame& f, const std::string& i_path, const std::string& j_path,
                    std::int64_t first_row, long k) {
  const Eigen::Index n = f.size();
  const IndexArray &i = f.contact_i(), &j = f.contact_j();
  for (Eigen::Index c = 0; c < i.size(); ++c) {
    const std::string row = ": row " + std::to_string(first_row + c) + " (frame " +
                            std::to_string(k) + ", contact " + std::to_string(c) + "): expected ";
    if (i[c] < 0 || i[c] >= n) {
      throw h5::Error(i_path + row + "a particle index in [0, " + std::to_string(n) + "), got " +
                      std::to_string(i[c]));
    }
    if (!((partner::is_particle(j[c]) && j[c] < n) || partner::is_wall(j[c])) || j[c] == i[c]) {
      throw h5::Error(j_path + row + "a particle index in [0, " + std::to_string(n) +
                      ") other than i (" + std::to_string(i[c]) +
                      ") or a wall code -2 (x_low) to -8 "
                      "(cylinder), got " +
                      std::to_string(j[c]));
    }
  }
}
}  // namespace

void FrameReader::Impl::read_contacts(long k, Frame& f) const {
  const auto first = static_cast<hsize_t>(contact_offset[k]);
  const auto m = static_cast<Eigen::Index>(contact_count[k]);
  PropertyTable& table = f.add_contacts(m);
  for (const ContactColumn& c : contact_columns) {
    h5::read_column(c.dataset.id(), c.path, first, static_cast<hsize_t>(m), table.add(c.property));
  }
  check_partners(f, contact_columns[0].path, contact_columns[1].path, contact_offset[k], k);
}

// Frame k without its container.
Frame FrameReader::Impl::read_particles(long k) const {
  Frame f;
  f.resize(info.particles, info.dim);
  read_element(*position, k, f.particles.column(0));
  if (!ours) f.radius().setConstant(default_radius);
  for (const ElementColumn& c : columns) {
    read_element(c.element, k, f.particles.add(c.property));
    if (c.property.name == "id") check_unique_ids(f, c.element.path(), k);
  }
  for (const ElementColumn& o : observables)
    read_element(o.element, k, f.observables.add(o.property));
  f.step = steps[k];
  if (!times.empty()) f.time = times[k];
  return f;
}

Frame FrameReader::Impl::read(long k) const {
  Frame f = read_particles(k);
  if (!ours) {
    f.container = box_container(k, f);
    return f;
  }
  f.container = container_at(k);
  if (edges) check_edges_agree(k, f.container);
  if (info.has_contacts) read_contacts(k, f);
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

FrameReader::WallPlacements FrameReader::wall_placements() const { return impl_->allowed; }

void FrameReader::place_walls_like(const std::array<bool, 3>& settled,
                                   const std::array<bool, 3>& centred) {
  for (int a = 0; a < 3; ++a) {
    if (settled[a] && impl_->allowed.at_zero[a] && impl_->allowed.centred[a])
      impl_->centred[a] = centred[a];
  }
}

Frame FrameReader::read(long index) const {
  h5::silence_error_stack();
  if (index < 0 || index >= impl_->info.frames) {
    throw InternalError(impl_->name + ": frame " + std::to_string(index) +
                        " requested, the file has " + std::to_string(impl_->info.frames));
  }
  return h5::input_errors_of(impl_->name, [&] { return impl_->read(index); });
}

}  // namespace granpipe
