// frames.h5: round trips, other tools' H5MD files, damaged files, and a writer killed
// mid-run (every frame the reader reports must be exactly what was written).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <tuple>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/frame_store.hpp"
#include "granpipe/version.hpp"
#include "plugin_harness.hpp"

namespace fs = std::filesystem;
using namespace granpipe;

namespace {

// Bit patterns, so that -0.0 and NaN payloads count too.
template <class A, class B>
bool same_bits(const A& a, const B& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.derived().data(), b.derived().data(),
                     sizeof(typename A::Scalar) * static_cast<std::size_t>(a.size())) == 0;
}

// A value with a full mantissa that depends on every index.
double value(long frame, long i, int a, int salt) {
  return std::sin(0.37 * static_cast<double>(frame) + 1.13 * static_cast<double>(i) + 0.71 * a +
                  2.9 * salt) *
         (1.0 + 1e-3 * static_cast<double>(frame));
}

struct Optional {
  bool velocity = true, angular = true, contacts = true, supports = true;
};

// Columns a plugin might add: integer pairs per particle, a real per particle, a real
// vector per contact, and per-frame observables.
const Property kSupports{"supports", Scope::Particle, ValueType::Integer, 2, "", "left, right"};
const Property kVolume{"voronoi_volume", Scope::Particle, ValueType::Real, 1, "length^3", "cell"};
const Property kHistory{"tangential_history", Scope::Contact, ValueType::Real,
                        kDimComponents,       "length",       "tangential spring"};
const Property kTap{"tap", Scope::Frame, ValueType::Integer, 1, "", "tap number"};
const Property kAmplitude{"amplitude", Scope::Frame, ValueType::Real, 1, "1", "tap amplitude"};

template <class Fill>
void fill_columns(Coordinates& c, Fill value) {
  for (Eigen::Index i = 0; i < c.rows(); ++i)
    for (int a = 0; a < c.cols(); ++a) c(i, a) = value(i, a);
}

void add_contacts(Frame& f, long k, Eigen::Index n, Eigen::Index m) {
  PropertyTable& c = f.add_contacts(m);
  for (Eigen::Index q = 0; q < m; ++q) {
    f.contact_i()[q] = q % n;
    f.contact_j()[q] = q % 2 ? (q + 1) % n : partner::wall(Wall::ZLow);
  }
  Eigen::ArrayXd& overlap = c.add<Eigen::ArrayXd>(*find_standard("overlap", Scope::Contact));
  for (Eigen::Index q = 0; q < m; ++q) overlap[q] = 1e-3 * std::abs(value(k, q, 0, 4));
  int salt = 5;
  for (const char* name : {"normal_force", "tangential_force", "point"}) {
    fill_columns(c.add<Coordinates>(*find_standard(name, Scope::Contact)),
                 [&](Eigen::Index q, int a) { return value(k, q, a, salt); });
    ++salt;
  }
  fill_columns(c.add<Coordinates>(kHistory),
               [&](Eigen::Index q, int a) { return value(k, q, a, 11); });
}

void add_contacts(Frame& f, long k, Eigen::Index n) {
  // A different number of contacts every frame, none at all in frame 2.
  add_contacts(f, k, n, k == 2 ? 0 : 1 + (k * 5) % 7);
}

// Frame k of a synthetic run: every value a function of k, every optional column present
// unless switched off, a container exercising every field.
Frame make_frame(long k, int dim, Eigen::Index n, Optional with = {}) {
  Frame f;
  f.resize(n, dim);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int a = 0; a < dim; ++a) f.position()(i, a) = 10.0 * value(k, i, a, 0);
    f.radius()[i] = 0.5 + 0.1 * std::abs(value(k, i, 0, 1));
    f.id()[i] = 1000 + 7 * i;
    f.species()[i] = static_cast<std::int32_t>((i + k) % 3);
  }
  if (with.velocity) {
    fill_columns(f.add("velocity").as<Coordinates>(),
                 [&](Eigen::Index i, int a) { return value(k, i, a, 2); });
  }
  if (with.angular) {
    fill_columns(f.add("angular_velocity").as<Coordinates>(),
                 [&](Eigen::Index i, int a) { return value(k, i, a, 3); });
  }
  if (with.supports) {
    auto& s = f.particles.add<ValueTable<std::int64_t>>(kSupports);
    Eigen::ArrayXd& volume = f.particles.add<Eigen::ArrayXd>(kVolume);
    for (Eigen::Index i = 0; i < n; ++i) {
      s(i, 0) = i % 3 == 0 ? partner::none : partner::wall(Wall::YLow);
      s(i, 1) = (i + k) % n;
      volume[i] = value(k, i, 0, 12);
    }
  }
  if (with.contacts) add_contacts(f, k, n);
  Container& box = f.container;
  box.shape = k % 2 ? ContainerShape::Cylinder : ContainerShape::Box;
  box.lo = Eigen::Vector3d(-1.0, -2.0, -3.0) * (1.0 + 0.01 * static_cast<double>(k));
  box.hi = Eigen::Vector3d(4.0, 5.0, 6.0 + value(k, 0, 0, 8));
  box.boundary = {{{Boundary::Periodic, Boundary::Periodic},
                   {Boundary::Wall, Boundary::Open},
                   {Boundary::Wall, Boundary::Wall}}};
  box.cylinder_radius = 2.5 + 0.1 * static_cast<double>(k);
  box.cylinder_center = Eigen::Vector2d(0.25, -0.5);
  box.wall_offset = Eigen::Vector3d(0.0, 0.0, 0.01 * value(k, 0, 0, 9));
  box.wall_velocity = Eigen::Vector3d(0.0, 0.0, value(k, 0, 0, 10));
  f.time = 0.001 * static_cast<double>(k) + 1e-12;
  f.step = 100 * k + 3;
  f.set_observable(kTap, static_cast<std::int64_t>(k / 2));
  f.set_observable(kAmplitude, value(k, 0, 0, 13));
  return f;
}

void expect_same_container(const Container& a, const Container& b) {
  EXPECT_EQ(a.shape, b.shape);
  EXPECT_TRUE(same_bits(a.lo, b.lo));
  EXPECT_TRUE(same_bits(a.hi, b.hi));
  EXPECT_EQ(a.boundary, b.boundary);
  EXPECT_EQ(std::memcmp(&a.cylinder_radius, &b.cylinder_radius, sizeof(double)), 0);
  EXPECT_TRUE(same_bits(a.cylinder_center, b.cylinder_center));
  EXPECT_TRUE(same_bits(a.wall_offset, b.wall_offset));
  EXPECT_TRUE(same_bits(a.wall_velocity, b.wall_velocity));
}

// The same columns, in the same order, with the same properties and bits.
void expect_same_table(const PropertyTable& a, const PropertyTable& b) {
  ASSERT_EQ(a.rows(), b.rows());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Column &p = a.column(k), &q = b.column(k);
    ASSERT_EQ(p.name(), q.name());
    EXPECT_TRUE(p.property().matches(q.property())) << p.name();
    EXPECT_EQ(p.property().unit, q.property().unit) << p.name();
    EXPECT_EQ(p.property().doc, q.property().doc) << p.name();
    ASSERT_EQ(p.storage().index(), q.storage().index()) << p.name();
    std::visit(
        [&](const auto& x) {
          using A = std::decay_t<decltype(x)>;
          EXPECT_TRUE(same_bits(x, std::get<A>(q.storage()))) << p.name();
        },
        p.storage());
  }
}

void expect_same_frame(const Frame& a, const Frame& b) {
  ASSERT_EQ(a.dim, b.dim);
  expect_same_table(a.particles, b.particles);
  expect_same_table(a.observables, b.observables);
  ASSERT_EQ(a.contacts.has_value(), b.contacts.has_value());
  if (a.contacts) expect_same_table(*a.contacts, *b.contacts);
  expect_same_container(a.container, b.container);
  EXPECT_EQ(std::memcmp(&a.time, &b.time, sizeof(double)), 0);
  EXPECT_EQ(a.step, b.step);
}

class FrameStore : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("granpipe_frame_store_" + std::to_string(getpid()) + "_" + t->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name) const { return dir_ / name; }

  // Writes `frames` frames of make_frame and closes the file.
  fs::path write(const std::string& name, long frames, int dim, Eigen::Index n,
                 Optional with = {}) {
    const fs::path p = file(name);
    FrameWriter w(p, R"({"name": "test"})");
    for (long k = 0; k < frames; ++k) w.append(make_frame(k, dim, n, with));
    w.close();
    return p;
  }

  fs::path dir_;
};

TEST_F(FrameStore, RoundTripIsBitIdenticalWithEveryOptionalArray) {
  for (int dim : {2, 3}) {
    const fs::path p = write("full" + std::to_string(dim) + ".h5", 5, dim, 17);
    FrameReader r(p);
    ASSERT_EQ(r.frames(), 5);
    for (long k = 0; k < 5; ++k) expect_same_frame(make_frame(k, dim, 17), r.read(k));
    const FrameFileInfo& info = r.info();
    EXPECT_EQ(info.particles, 17);
    EXPECT_EQ(info.dim, dim);
    EXPECT_TRUE(info.complete);
    EXPECT_TRUE(info.granpipe_file);
    for (const char* c : {"radius", "velocity", "angular_velocity", "supports", "voronoi_volume"}) {
      EXPECT_TRUE(info.has(c)) << c;
    }
    EXPECT_TRUE(info.has_contacts);
    ASSERT_EQ(info.observables.size(), 2u);
    EXPECT_EQ(info.observables[0].name, "tap");
    EXPECT_EQ(info.observables[1].unit, "1");
    EXPECT_EQ(info.group, "all");
    EXPECT_EQ(info.creator, std::string("granpipe ") + GRANPIPE_VERSION);
  }
}

TEST_F(FrameStore, RoundTripIsBitIdenticalWithNoOptionalArray) {
  const Optional none{false, false, false, false};
  const fs::path p = write("bare.h5", 4, 3, 9, none);
  FrameReader r(p);
  ASSERT_EQ(r.frames(), 4);
  for (long k = 0; k < 4; ++k) expect_same_frame(make_frame(k, 3, 9, none), r.read(k));
  EXPECT_FALSE(r.info().has("velocity") || r.info().has("angular_velocity") ||
               r.info().has_contacts || r.info().has("supports"));
}

TEST_F(FrameStore, ContactTablesLargerThanOneWrittenBlockRoundTrip) {
  // The writer copies a contact column into HDF5's row order in blocks of 2^16 rows.
  const Optional none{false, false, false, false};
  const fs::path p = file("blocks.h5");
  std::vector<Frame> frames;
  FrameWriter w(p, R"({"name": "test"})");
  for (const Eigen::Index m : {Eigen::Index{2} * 65536 + 5, Eigen::Index{65536}}) {
    frames.push_back(make_frame(static_cast<long>(frames.size()), 3, 50, none));
    add_contacts(frames.back(), static_cast<long>(frames.size()), 50, m);
    w.append(frames.back());
  }
  w.close();
  FrameReader r(p);
  ASSERT_EQ(r.frames(), 2);
  for (long k = 0; k < 2; ++k) expect_same_frame(frames[static_cast<std::size_t>(k)], r.read(k));
}

TEST_F(FrameStore, EmptyAndOneParticleFramesRoundTrip) {
  for (Eigen::Index n : {0, 1}) {
    std::string name = "n";  // not "n" + to_string(n): GCC 12 warns of a restrict overlap
    name += std::to_string(n) + ".h5";
    const fs::path p = write(name, 3, 3, n, {true, true, false, true});
    FrameReader r(p);
    ASSERT_EQ(r.frames(), 3);
    for (long k = 0; k < 3; ++k) {
      expect_same_frame(make_frame(k, 3, n, {true, true, false, true}), r.read(k));
    }
  }
}

TEST_F(FrameStore, NonFinitePositionsAreStoredAsGiven) {
  // Rejecting them is Frame::check's job; the store must not hide them.
  Frame f = make_frame(0, 2, 3);
  f.position()(1, 0) = std::numeric_limits<double>::quiet_NaN();
  f.position()(2, 1) = -std::numeric_limits<double>::infinity();
  const fs::path p = file("nan.h5");
  FrameWriter w(p, "{}");
  w.append(f);
  w.close();
  expect_same_frame(f, FrameReader(p).read(0));
}

// A dump of a pouring run changes its count: an input's doing, refused as such (it was an
// internal error, exit 1).
TEST_F(FrameStore, AFrameOfAnotherParticleCountIsRefusedAsInput) {
  const fs::path p = file("count.h5");
  FrameWriter w(p, "{}");
  w.append(make_frame(0, 3, 5));
  const Frame fewer = make_frame(1, 3, 4);
  EXPECT_EQ(test::input_error_of([&] { w.append(fewer); }),
            p.string() + ": frame 1 (step " + std::to_string(fewer.step) +
                ") has 4 particles, the first frame 5: expected one particle count in a frames "
                "file (with output.save_frames false, frames whose count changes are analysed "
                "unsaved)");
}

// The lammps_dump source gives frames of a dump without ITEM: TIME or dt an undefined time:
// their frames file was refused by its own reader ("expected a finite time, got nan").
TEST_F(FrameStore, AnUndefinedTimeIsStoredAndReadAsSuch) {
  const fs::path p = file("undefined_time.h5");
  FrameWriter w(p, "{}");
  for (long k = 0; k < 2; ++k) {
    Frame f = make_frame(k, 3, 4);
    f.time = std::nan("");
    w.append(f);
  }
  w.close();
  const FrameReader r(p);
  EXPECT_TRUE(std::isnan(r.read(0).time) && std::isnan(r.read(1).time));
}

TEST_F(FrameStore, WriterThatNeverClosedLeavesAnIncompleteButReadableFile) {
  const fs::path p = file("open.h5");
  {
    FrameWriter w(p, "{}");
    for (long k = 0; k < 3; ++k) w.append(make_frame(k, 3, 5));
  }
  FrameReader r(p);
  EXPECT_FALSE(r.info().complete);
  ASSERT_EQ(r.frames(), 3);
  for (long k = 0; k < 3; ++k) expect_same_frame(make_frame(k, 3, 5), r.read(k));
}

TEST_F(FrameStore, FileClosedBeforeAnyFrameHasNoFrames) {
  const fs::path p = file("none.h5");
  FrameWriter w(p, "{}");
  w.close();
  FrameReader r(p);
  EXPECT_EQ(r.frames(), 0);
  EXPECT_TRUE(r.info().complete);
}

TEST_F(FrameStore, WriterRefusesAnExistingFile) {
  const fs::path p = write("exists.h5", 1, 3, 2);
  const std::string msg = test::input_error_of([&] { FrameWriter w(p, "{}"); });
  EXPECT_NE(msg.find(p.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("already exists"), std::string::npos) << msg;
  EXPECT_EQ(FrameReader(p).frames(), 1);  // untouched
}

TEST_F(FrameStore, FramesOfOneFileMustMatchTheFirst) {
  FrameWriter w(file("mixed.h5"), "{}");
  w.append(make_frame(0, 3, 5));
  EXPECT_THROW(w.append(make_frame(1, 3, 6)), InputError);  // the count: the input's doing
  EXPECT_THROW(w.append(make_frame(1, 2, 5)), InternalError);
  EXPECT_THROW(w.append(make_frame(1, 3, 5, {false, true, true, true})), InternalError);
  w.append(make_frame(1, 3, 5));
  EXPECT_EQ(w.frames(), 2);
}

// ---- Other tools' files, written here with the HDF5 C API ----

// An HDF5 identifier closed at the end of its scope.
struct Id {
  hid_t id;
  explicit Id(hid_t h) : id(h) {}
  ~Id() { H5Idec_ref(id); }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  operator hid_t() const { return id; }
};

hid_t make_group(hid_t loc, const char* name) {
  return H5Gcreate2(loc, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
}

void put_dataset(hid_t loc, const char* name, hid_t type, std::vector<hsize_t> dims,
                 const void* data) {
  Id space(dims.empty() ? H5Screate(H5S_SCALAR)
                        : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  Id ds(H5Dcreate2(loc, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
}

void put_int_attribute(hid_t loc, const char* name, std::vector<int> values, bool scalar) {
  const hsize_t n = values.size();
  Id space(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr));
  Id a(H5Acreate2(loc, name, H5T_NATIVE_INT, space, H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(a, H5T_NATIVE_INT, values.data());
}

// Fixed-length, space-padded strings, as a Fortran writer would leave them.
void put_string_attribute(hid_t loc, const char* name, const std::vector<std::string>& values) {
  std::size_t width = 8;
  for (const auto& v : values) width = std::max(width, v.size());
  std::string buffer;
  for (const auto& v : values) buffer += v + std::string(width - v.size(), ' ');
  Id type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type, width);
  H5Tset_strpad(type, H5T_STR_SPACEPAD);
  const hsize_t n = values.size();
  Id space(H5Screate_simple(1, &n, nullptr));
  Id a(H5Acreate2(loc, name, type, space, H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(a, type, buffer.data());
}

// The reader's refusal of `p`, without the file name it starts with.
std::string reader_error(const fs::path& p) {
  try {
    FrameReader r(p);
    for (long k = 0; k < r.frames(); ++k) r.read(k);
  } catch (const InputError& e) {
    const std::string m = e.what(), prefix = p.string() + ": ";
    return m.starts_with(prefix) ? m.substr(prefix.size()) : m;
  }
  return "no error";
}

// An H5MD file as another MD code writes it: float positions, explicit clocks, a fixed
// box, species fixed in time, velocities sampled every other frame, no id, no radius.
// `z_shift` moves every particle along the walled axis z (edge 6).
void write_foreign(const fs::path& p, bool second_group, float z_shift = 0.0f) {
  Id f(H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  Id h5md(make_group(f, "h5md"));
  put_int_attribute(h5md, "version", {1, 0}, false);
  Id creator(make_group(h5md, "creator"));
  put_string_attribute(creator, "name", {"othermd"});
  Id particles(make_group(f, "particles"));
  Id atoms(make_group(particles, "atoms"));
  Id box(make_group(atoms, "box"));
  put_int_attribute(box, "dimension", {3}, true);
  put_string_attribute(box, "boundary", {"periodic", "periodic", "none"});
  const double edges[3] = {4.0, 5.0, 6.0};
  put_dataset(box, "edges", H5T_NATIVE_DOUBLE, {3}, edges);

  Id position(make_group(atoms, "position"));
  float x[3][4][3];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 4; ++i)
      for (int a = 0; a < 3; ++a)
        x[k][i][a] = 0.25f * static_cast<float>(k + i + a) + (a == 2 ? z_shift : 0.0f);
  put_dataset(position, "value", H5T_NATIVE_FLOAT, {3, 4, 3}, x);
  const std::int64_t steps[3] = {10, 20, 30};
  const double times[3] = {0.5, 1.0, 1.5};
  put_dataset(position, "step", H5T_NATIVE_INT64, {3}, steps);
  put_dataset(position, "time", H5T_NATIVE_DOUBLE, {3}, times);

  Id velocity(make_group(atoms, "velocity"));
  const double v[2][4][3] = {};
  const std::int64_t vsteps[2] = {10, 30};
  put_dataset(velocity, "value", H5T_NATIVE_DOUBLE, {2, 4, 3}, v);
  put_dataset(velocity, "step", H5T_NATIVE_INT64, {2}, vsteps);

  const int species[4] = {2, 0, 1, 2};
  put_dataset(atoms, "species", H5T_NATIVE_INT, {4}, species);
  if (second_group) Id walls(make_group(particles, "walls"));
}

TEST_F(FrameStore, ReadsAnotherToolsFile) {
  const fs::path p = file("foreign.h5");
  write_foreign(p, false);
  FrameReader r(p, "", 0.75);
  const FrameFileInfo& info = r.info();
  EXPECT_EQ(info.group, "atoms");
  EXPECT_EQ(info.creator, "othermd");
  EXPECT_FALSE(info.granpipe_file);
  EXPECT_TRUE(info.complete);
  EXPECT_FALSE(info.has("radius") || info.has_contacts || info.has("supports"));
  // Velocities exist only at every other step: not at every frame, so not used.
  EXPECT_FALSE(info.has("velocity"));
  ASSERT_EQ(r.frames(), 3);
  ASSERT_EQ(info.particles, 4);
  for (long k = 0; k < 3; ++k) {
    const Frame f = r.read(k);
    ASSERT_EQ(f.dim, 3);
    for (int i = 0; i < 4; ++i) {
      for (int a = 0; a < 3; ++a) EXPECT_EQ(f.position()(i, a), 0.25 * (k + i + a));
      EXPECT_EQ(f.radius()[i], 0.75);
      EXPECT_EQ(f.id()[i], i);  // no id element: ids are the indices
    }
    EXPECT_EQ(f.species()[0], 2);
    EXPECT_EQ(f.species()[2], 1);
    EXPECT_EQ(f.step, 10 * (k + 1));
    EXPECT_EQ(f.time, 0.5 * static_cast<double>(k + 1));
    EXPECT_EQ(f.observables.size(), 0u);
    EXPECT_EQ(f.container.shape, ContainerShape::Box);
    EXPECT_EQ(f.container.lo, Eigen::Vector3d::Zero());
    EXPECT_EQ(f.container.hi.head(3), Eigen::Vector3d(4.0, 5.0, 6.0));
    EXPECT_TRUE(f.container.periodic(0) && f.container.periodic(1));
    EXPECT_EQ(f.container.boundary[2][0], Boundary::Wall);
    EXPECT_EQ(f.container.boundary[2][1], Boundary::Wall);
    EXPECT_FALSE(f.has("velocity"));
  }
}

// A radius sampled on a clock of its own (steps 10 and 30 of 10, 20, 30) was left out as an
// optional element is, and the default radius read for every particle, exit 0; ids and
// species so became the rows' order and 0.
TEST_F(FrameStore, ARadiusIdOrSpeciesMissingAtSomeStepsIsRefused) {
  for (const std::string name : {"radius", "id", "species"}) {
    const fs::path p = file("foreign_" + name + ".h5");
    write_foreign(p, false);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      Id atoms(H5Gopen2(f, "particles/atoms", H5P_DEFAULT));
      if (name == "species") {
        EXPECT_GE(H5Ldelete(atoms, "species", H5P_DEFAULT), 0);
      }
      Id element(make_group(atoms, name.c_str()));
      const std::int64_t values[2][4] = {{1, 2, 3, 4}, {1, 2, 3, 4}};
      const std::int64_t steps[2] = {10, 30};
      put_dataset(element, "value", H5T_NATIVE_INT64, {2, 4}, values);
      put_dataset(element, "step", H5T_NATIVE_INT64, {2}, steps);
    }
    EXPECT_EQ(reader_error(p), "/particles/atoms/" + name + "/value: expected " +
                                   (name == "id" ? "an " : "a ") + name +
                                   " at every step of the positions, got one on a clock of its "
                                   "own that misses some");
  }
}

// Of a radius written twice at one step the second sample was left unread without a word,
// and steps out of order were called a clock that misses some.
TEST_F(FrameStore, AnElementWhoseStepsDoNotRiseIsRefused) {
  const std::vector<std::vector<std::int64_t>> clocks{{10, 20, 20, 30}, {10, 30, 20, 40}};
  for (std::size_t c = 0; c < clocks.size(); ++c) {
    const fs::path p = file("steps_" + std::to_string(c) + ".h5");
    write_foreign(p, false);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      Id atoms(H5Gopen2(f, "particles/atoms", H5P_DEFAULT));
      Id element(make_group(atoms, "radius"));
      const double values[4][4] = {{1, 1, 1, 1}, {1, 1, 1, 1}, {2, 2, 2, 2}, {1, 1, 1, 1}};
      put_dataset(element, "value", H5T_NATIVE_DOUBLE, {4, 4}, values);
      put_dataset(element, "step", H5T_NATIVE_INT64, {4}, clocks[c].data());
    }
    EXPECT_EQ(reader_error(p), c == 0 ? "/particles/atoms/radius/step: expected rising steps, got "
                                        "20 at sample 2 after 20"
                                      : "/particles/atoms/radius/step: expected rising steps, got "
                                        "20 at sample 2 after 30");
  }
}

// A radius linked to nothing (a soft link to a removed object, an external link to a
// missing file) read as no radius: the default radius stood for the file's, exit 0.
TEST_F(FrameStore, ALinkThatLeadsNowhereIsRefused) {
  for (const bool external : {false, true}) {
    const fs::path p = file(external ? "external.h5" : "soft.h5");
    write_foreign(p, false);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      Id atoms(H5Gopen2(f, "particles/atoms", H5P_DEFAULT));
      if (external) {
        H5Lcreate_external("missing.h5", "/radius", atoms, "radius", H5P_DEFAULT, H5P_DEFAULT);
      } else {
        H5Lcreate_soft("/particles/atoms/removed", atoms, "radius", H5P_DEFAULT, H5P_DEFAULT);
      }
    }
    EXPECT_EQ(reader_error(p),
              "/particles/atoms/radius: expected a group or dataset, got a link that leads to "
              "none (a soft link to a removed object or an external link to a missing file)");
  }
}

// An element "a b" in a granpipe file (whose columns are all read): no column can have that
// name (analyzers and writers name columns in JSON paths and headers); it ended in an
// internal error, exit 1.
TEST_F(FrameStore, AnElementNamedAsNoColumnCanBeIsRefused) {
  const fs::path p = write("name.h5", 3, 2, 4, Optional{false, false, false, false});
  {
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    Id element(make_group(f, "particles/all/a b"));
    const double charge[3][4] = {};
    const std::int64_t steps[3] = {0, 1, 2};
    put_dataset(element, "value", H5T_NATIVE_DOUBLE, {3, 4}, charge);
    put_dataset(element, "step", H5T_NATIVE_INT64, {3}, steps);
  }
  EXPECT_EQ(reader_error(p),
            "/particles/all/a b/value: expected an element name of letters, digits and _, not "
            "starting with a digit (a column's name), got \"a b\"");
}

// A file of another H5MD major version was read as 1.x, whose layout it need not have.
TEST_F(FrameStore, AnotherH5mdMajorVersionIsRefused) {
  const fs::path p = file("h5md_2.h5");
  write_foreign(p, false);
  {
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    Id h5md(H5Gopen2(f, "h5md", H5P_DEFAULT));
    EXPECT_GE(H5Adelete(h5md, "version"), 0);
    put_int_attribute(h5md, "version", {2, 0}, false);
  }
  EXPECT_EQ(reader_error(p), "/h5md@version: expected H5MD 1.x, got 2.0");
}

// A granpipe file without its radius element read every radius as the default and
// blamed particle 0 for a radius of 0; the extension's list of columns names it.
TEST_F(FrameStore, AColumnTheFileListsButLacksIsRefused) {
  const fs::path p = write("no_radius.h5", 3, 2, 4, Optional{false, false, false, false});
  {
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    Id all(H5Gopen2(f, "particles/all", H5P_DEFAULT));
    EXPECT_GE(H5Ldelete(all, "radius", H5P_DEFAULT), 0);
  }
  EXPECT_EQ(reader_error(p),
            "/particles/all/radius: missing, where /granpipe@particle_columns lists it (a "
            "damaged granpipe file?)");
}

// Clocks: a step of 2^63 + 5 stored unsigned was clamped to 2^63 - 1; a fixed clock's
// step past 64 bits wrapped round to a negative one; a NaN time labelled its frame.
TEST_F(FrameStore, ClocksBeyondTheirNumbersAreRefused) {
  auto with_clock = [&](const std::string& name, const char* clock, hid_t type,
                        const std::vector<hsize_t>& shape, const void* values) {
    const fs::path p = file(name);
    write_foreign(p, false);
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    Id position(H5Gopen2(f, "particles/atoms/position", H5P_DEFAULT));
    EXPECT_GE(H5Ldelete(position, clock, H5P_DEFAULT), 0);
    put_dataset(position, clock, type, shape, values);
    return p;
  };
  const std::uint64_t huge[3] = {10, 20, (std::uint64_t{1} << 63) + 5};
  EXPECT_EQ(reader_error(with_clock("huge.h5", "step", H5T_NATIVE_UINT64, {3}, huge)),
            "/particles/atoms/position/step: expected integers up to 9223372036854775807, got "
            "9223372036854775813");
  const std::int64_t increment = std::int64_t{1} << 62;
  EXPECT_EQ(reader_error(with_clock("wrap.h5", "step", H5T_NATIVE_INT64, {}, &increment)),
            "/particles/atoms/position/step: sample 2: expected a step within 64-bit integers, "
            "got 2 x 4611686018427387904 + 0");
  // NaN is an undefined time (a dump without ITEM: TIME or dt; granpipe refused its own
  // frames of one), read as such.
  const double nan_time[3] = {0.5, std::nan(""), 1.5};
  const FrameReader undefined(with_clock("nan.h5", "time", H5T_NATIVE_DOUBLE, {3}, nan_time));
  EXPECT_TRUE(std::isnan(undefined.read(1).time));
  EXPECT_EQ(undefined.read(2).time, 1.5);
  const double vast = 1e308;  // sample 2 at 2e308
  EXPECT_EQ(reader_error(with_clock("inf.h5", "time", H5T_NATIVE_DOUBLE, {}, &vast)),
            "/particles/atoms/position/time: sample 2: expected a finite time (or NaN, "
            "undefined), got inf");
}

// HDF5 converts without a word: a species of 2^40 was read as 2147483647 and an id of
// 1.5 as 1. Reals that are whole numbers are integers still.
TEST_F(FrameStore, IntegersBeyondTheirColumnOrNotWholeAreRefused) {
  auto with_species = [&](const std::string& name, hid_t type, const void* values) {
    const fs::path p = file(name);
    write_foreign(p, false);
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    Id atoms(H5Gopen2(f, "particles/atoms", H5P_DEFAULT));
    EXPECT_GE(H5Ldelete(atoms, "species", H5P_DEFAULT), 0);
    put_dataset(atoms, "species", type, {4}, values);
    return p;
  };
  const std::int64_t wide[4] = {2, std::int64_t{1} << 40, 1, 2};
  EXPECT_EQ(reader_error(with_species("wide.h5", H5T_NATIVE_INT64, wide)),
            "/particles/atoms/species: expected integers from -2147483648 to 2147483647, got "
            "1099511627776");
  const double half[4] = {2, 0.5, 1, 2};
  EXPECT_EQ(reader_error(with_species("half.h5", H5T_NATIVE_DOUBLE, half)),
            "/particles/atoms/species: expected whole numbers, got 0.5");
  const double whole[4] = {2, 0, 1, 2};
  const fs::path p = with_species("whole.h5", H5T_NATIVE_DOUBLE, whole);
  EXPECT_EQ(FrameReader(p).read(0).species()[2], 1);
  // Species written as element names: it said "another data type".
  Id text(H5Tcopy(H5T_C_S1));
  H5Tset_size(text, 2);
  const char names[4][2] = {{'C', 'u'}, {'F', 'e'}, {'C', 'u'}, {'N', 'i'}};
  EXPECT_EQ(reader_error(with_species("names.h5", text, names)),
            "/particles/atoms/species: expected integers (or an enumeration), got strings");
}

// A clock shorter than its values read as fewer frames (3 positions, 2 times: 2 frames),
// exit 0. H5MD gives every sample its step and time.
TEST_F(FrameStore, AnotherToolsClockShorterThanItsValuesIsRefused) {
  for (const char* clock : {"step", "time"}) {
    const fs::path p = file(std::string("short_") + clock + ".h5");
    write_foreign(p, false);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      Id position(H5Gopen2(f, "particles/atoms/position", H5P_DEFAULT));
      ASSERT_GE(H5Ldelete(position, clock, H5P_DEFAULT), 0);
      const std::int64_t steps[2] = {10, 20};
      const double times[2] = {0.5, 1.0};
      if (std::string(clock) == "step") {
        put_dataset(position, "step", H5T_NATIVE_INT64, {2}, steps);
      } else {
        put_dataset(position, "time", H5T_NATIVE_DOUBLE, {2}, times);
      }
    }
    EXPECT_EQ(reader_error(p), "/particles/atoms/position/" + std::string(clock) +
                                   ": expected a row for each of the 3 samples of "
                                   "/particles/atoms/position/value, got 2 (damaged file)");
  }
}

// Lengths are read as stored: positions and box edges in different units gave a packing
// fraction 1000 times off.
TEST_F(FrameStore, LengthsInDifferentUnitsAreRefusedNamingBoth) {
  const auto with_units = [&](const std::string& name, const std::string& position,
                              const std::string& edges) {
    const fs::path p = file(name);
    write_foreign(p, false);
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    Id value(H5Dopen2(f, "particles/atoms/position/value", H5P_DEFAULT));
    put_string_attribute(value, "unit", {position});
    Id box_edges(H5Dopen2(f, "particles/atoms/box/edges", H5P_DEFAULT));
    if (!edges.empty()) put_string_attribute(box_edges, "unit", {edges});
    return p;
  };
  EXPECT_EQ(reader_error(with_units("mixed.h5", "nm", "angstrom")),
            "/particles/atoms/box/edges@unit: expected \"nm\", the unit of "
            "/particles/atoms/position/value (granpipe reads lengths as stored, in one unit), got "
            "\"angstrom\"");
  EXPECT_EQ(reader_error(with_units("same.h5", "nm", "nm")), "no error");
  // One length written two ways (MDAnalysis reads A, Angstrom and angstrom alike; H5MD
  // allows a leading factor).
  EXPECT_EQ(reader_error(with_units("spelt.h5", "A", "Angstrom")), "no error");
  EXPECT_EQ(reader_error(with_units("factor.h5", "0.1 nm", "angstrom")), "no error");
  EXPECT_EQ(reader_error(with_units("glued.h5", "10nm", "1e-8 m")), "no error");
  EXPECT_EQ(reader_error(with_units("plus.h5", "+2 nm", "+2nm")), "no error");
  EXPECT_EQ(reader_error(with_units("ten.h5", "10 nm", "nm")),
            "/particles/atoms/box/edges@unit: expected \"10 nm\", the unit of "
            "/particles/atoms/position/value (granpipe reads lengths as stored, in one unit), got "
            "\"nm\"");
  EXPECT_EQ(reader_error(with_units("one_stated.h5", "nm", "")), "no error");
  // Names written out (MDAnalysis' "nanometer"), H5MD's power 1, and a unit stated as none.
  EXPECT_EQ(reader_error(with_units("named.h5", "nm", "nanometer")), "no error");
  EXPECT_EQ(reader_error(with_units("plural.h5", "metres", "m")), "no error");
  EXPECT_EQ(reader_error(with_units("femto.h5", "femtometre", "fm")), "no error");
  EXPECT_EQ(reader_error(with_units("micro.h5", "micrometers", "\u00b5m")), "no error");
  EXPECT_EQ(reader_error(with_units("power.h5", "nm+1", "nm")), "no error");
  EXPECT_EQ(reader_error(with_units("none.h5", "", "nm")), "no error");
  // An empty list of units was an internal error (exit 1).
  const fs::path empty = file("empty_list.h5");
  write_foreign(empty, false);
  {
    Id f(H5Fopen(empty.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    Id value(H5Dopen2(f, "particles/atoms/position/value", H5P_DEFAULT));
    put_string_attribute(value, "unit", {});
  }
  EXPECT_EQ(reader_error(empty),
            "/particles/atoms/position/value@unit: expected one unit, got 0 strings");
}

// H5MD boxes have no origin: walls go where the particles are, at [0, L] or [-L/2, L/2].
TEST_F(FrameStore, WallsOfAnotherToolsCentredBoxHoldItsParticles) {
  const fs::path centred = file("centred.h5");
  write_foreign(centred, false, -3.0f);  // z from -2.5 to -1.75: inside [-3, 3]
  const Frame f = FrameReader(centred).read(0);
  EXPECT_EQ(f.container.lo[2], -3.0);
  EXPECT_EQ(f.container.hi[2], 3.0);
  EXPECT_EQ(f.container.lo[0], 0.0);  // periodic sides keep the origin 0
  const fs::path outside = file("outside.h5");
  write_foreign(outside, false, -7.0f);
  try {
    FrameReader(outside).read(0);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(
        e.what(),
        (outside.string() +
         ": /particles/atoms/box/edges: frame 0: expected particle centres inside a box of "
         "edge 6 along z (at [0, L] or [-L/2, L/2]), got -6.5 to -5.75")
            .c_str());
  }
}

namespace {
// A plain H5MD file of T frames (steps 0, 1, ...): two particles at `x` in a walled box of
// edge 10.
template <std::size_t T>
void write_two_in_a_walled_box(const fs::path& p, const double (&x)[T][2][3]) {
  Id f(H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  Id particles(make_group(f, "particles"));
  Id all(make_group(particles, "all"));
  Id box(make_group(all, "box"));
  put_string_attribute(box, "boundary", {"none", "none", "none"});
  const double edges[3] = {10.0, 10.0, 10.0};
  put_dataset(box, "edges", H5T_NATIVE_DOUBLE, {3}, edges);
  Id position(make_group(all, "position"));
  put_dataset(position, "value", H5T_NATIVE_DOUBLE, {T, 2, 3}, x);
  std::int64_t steps[T];
  for (std::size_t k = 0; k < T; ++k) steps[k] = static_cast<std::int64_t>(k);
  put_dataset(position, "step", H5T_NATIVE_INT64, {T}, steps);
}
}  // namespace

// The walls go where the first frame's centres put them, in every frame: placed frame by
// frame, the same walls went at [0, 10] in frame 0 and [-5, 5] in frame 1.
TEST_F(FrameStore, WallsOfAnotherToolsBoxStayWhereTheFilesFramesPutThem) {
  // Two frames along x: the first's centres, then the second's.
  const auto two_frames = [&](const std::string& name, double first_x, double second_x) {
    const fs::path p = file(name);
    const double x[2][2][3] = {{{first_x, 2.0, 2.0}, {4.0, 5.0, 5.0}},
                               {{second_x, 2.0, 2.0}, {4.0, 5.0, 5.0}}};
    write_two_in_a_walled_box(p, x);
    return p;
  };
  // Frame 0 fits [0, 10] only (x up to 6), frame 1 [-5, 5] only.
  EXPECT_EQ(reader_error(two_frames("jump.h5", 6.0, -0.5)),
            "/particles/all/box/edges: frame 1: expected particle centres inside a box of edge "
            "10 along x at [0, L], where the file's frames put its walls, got -0.5 to 4 (H5MD "
            "stores no origin: walls that move by L/2 between frames are refused)");
  // Frame 0 fits both (a centred box's grains in its upper half), frame 1 [-5, 5] only: the
  // walls are at [-5, 5] in both frames.
  const FrameReader poured(two_frames("poured.h5", 0.5, -0.5));
  for (long k = 0; k < 2; ++k) {
    EXPECT_EQ(poured.read(k).container.lo[0], -5.0);
    EXPECT_EQ(poured.read(k).container.hi[0], 5.0);
  }
  // Both frames fit both: [0, 10].
  EXPECT_EQ(FrameReader(two_frames("either.h5", 0.5, 1.0)).read(1).container.lo[0], 0.0);
}

// Frame 0 decides an axis it fits one way only, whatever the later frames (which went on
// being read for the axes still open, and narrowed the decided one too): a grain escaped in
// frame 1 had frame 0 refused. A later frame whose centres are no numbers ends the
// placing: it is refused when read, not when the file is opened.
TEST_F(FrameStore, FrameZeroDecidesTheAxesItFitsOneWayOnly) {
  const fs::path escaped = file("escaped.h5");
  // x: frame 0 fits [-5, 5] only; y and z fit both in frame 0, so frame 1 is read.
  const double x[2][2][3] = {{{-1.0, 2.0, 2.0}, {1.0, 3.0, 3.0}},
                             {{100.0, 2.0, 2.0}, {1.0, 3.0, 3.0}}};
  write_two_in_a_walled_box(escaped, x);
  const FrameReader reader(escaped);
  const Frame first = reader.read(0);
  EXPECT_EQ(first.container.lo[0], -5.0);
  EXPECT_EQ(first.container.lo[2], 0.0);
  const std::string escape = test::input_error_of([&] { reader.read(1); });
  EXPECT_NE(escape.find("frame 1: expected particle centres inside a box of edge 10 along x"),
            std::string::npos)
      << escape;
  const fs::path late = file("late_nan.h5");
  const double y[2][2][3] = {{{2.0, 2.0, 2.0}, {4.0, 5.0, 5.0}},
                             {{std::nan(""), 2.0, 2.0}, {4.0, 5.0, 5.0}}};
  write_two_in_a_walled_box(late, y);
  const FrameReader opened(late);
  EXPECT_EQ(opened.read(0).container.lo[0], 0.0);
  EXPECT_EQ(test::input_error_of([&] { opened.read(1); }),
            late.string() +
                ": frame 1: particle 0 (id 0): expected a finite position, got nan in "
                "coordinate x");
}

// Walls are placed from the particle centres: a NaN among them is reported by the frame
// check, on its own axis, not as a box of range nan to nan (or on another axis).
TEST_F(FrameStore, NanPositionInAWalledBoxIsNamedByTheFrameCheck) {
  const double nan = std::nan("");
  for (const auto& [particle, axis] : {std::pair{0, 0}, {1, 0}, {0, 1}, {1, 2}}) {
    const fs::path p = file("nan_" + std::to_string(particle) + std::to_string(axis) + ".h5");
    double x[1][2][3] = {{{2.0, 2.0, 2.0}, {5.0, 5.0, 5.0}}};
    x[0][particle][axis] = nan;
    write_two_in_a_walled_box(p, x);
    EXPECT_EQ(test::input_error_of([&] { FrameReader(p).read(0); }),
              p.string() + ": frame 0: particle " + std::to_string(particle) + " (id " +
                  std::to_string(particle) +
                  "): expected a finite position, got nan in coordinate " + "xyz"[axis]);
  }
}

// A centre of 1e300 was printed with %f, a number of 300 digits; one just past the edge
// as the edge itself ("box of edge 10 ..., got 0.5 to 10").
TEST_F(FrameStore, ACentreOutsideTheBoxIsPrintedReadably) {
  for (const double z : {1e300, 10.000001}) {
    const fs::path p = file("outside.h5");
    const double x[1][2][3] = {{{2.0, 2.0, 0.5}, {5.0, 5.0, z}}};
    write_two_in_a_walled_box(p, x);
    EXPECT_EQ(test::input_error_of([&] { FrameReader(p).read(0); }),
              p.string() +
                  ": /particles/all/box/edges: frame 0: expected particle centres inside a box "
                  "of edge 10 along z (at [0, L] or [-L/2, L/2]), got 0.5 to " +
                  (z > 11 ? "1e+300" : "10.000001"));
  }
}

TEST_F(FrameStore, GroupChoosesAmongSeveralParticlesGroups) {
  const fs::path p = file("two_groups.h5");
  write_foreign(p, true);
  const std::string ambiguous = test::input_error_of([&] { FrameReader r(p); });
  EXPECT_NE(ambiguous.find("several particles groups (atoms, walls)"), std::string::npos)
      << ambiguous;
  EXPECT_EQ(FrameReader(p, "atoms").frames(), 3);
  const std::string missing = test::input_error_of([&] { FrameReader r(p, "grains"); });
  EXPECT_NE(missing.find("/particles/grains: no such particles group"), std::string::npos)
      << missing;
  const std::string no_position = test::input_error_of([&] { FrameReader r(p, "walls"); });
  EXPECT_NE(no_position.find("/particles/walls/position: missing"), std::string::npos)
      << no_position;
}

TEST_F(FrameStore, ReadsFixedClocksAndATimeDependentBox) {
  // H5MD 1.1 "fixed" storage: step and time are increments, their offsets attributes.
  const fs::path p = file("fixed_clock.h5");
  {
    Id f(H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
    Id particles(make_group(f, "particles"));
    Id all(make_group(particles, "all"));
    Id position(make_group(all, "position"));
    const double x[4][2][2] = {};
    put_dataset(position, "value", H5T_NATIVE_DOUBLE, {4, 2, 2}, x);
    const std::int64_t step = 5;
    put_dataset(position, "step", H5T_NATIVE_INT64, {}, &step);
    put_int_attribute(Id(H5Dopen2(position, "step", H5P_DEFAULT)), "offset", {100}, true);
    const double dt = 0.25;
    put_dataset(position, "time", H5T_NATIVE_DOUBLE, {}, &dt);
    Id box(make_group(all, "box"));
    put_string_attribute(box, "boundary", {"none", "periodic"});
    Id edges(make_group(box, "edges"));
    // A triclinic form of a rectangular box: diagonal matrices.
    const double e[4][2][2] = {
        {{1, 0}, {0, 2}}, {{1, 0}, {0, 3}}, {{1, 0}, {0, 4}}, {{1, 0}, {0, 5}}};
    put_dataset(edges, "value", H5T_NATIVE_DOUBLE, {4, 2, 2}, e);
    H5Lcreate_hard(position, "step", edges, "step", H5P_DEFAULT, H5P_DEFAULT);
  }
  FrameReader r(p);
  ASSERT_EQ(r.frames(), 4);
  for (long k = 0; k < 4; ++k) {
    const Frame fr = r.read(k);
    EXPECT_EQ(fr.step, 100 + 5 * k);
    EXPECT_EQ(fr.time, 0.25 * static_cast<double>(k));
    EXPECT_EQ(fr.container.hi[1], 2.0 + static_cast<double>(k));
    EXPECT_EQ(fr.container.boundary[0][0], Boundary::Wall);
    EXPECT_TRUE(fr.container.periodic(1));
  }
}

TEST_F(FrameStore, WrongPositionShapeIsAnInputErrorNamingTheDataset) {
  const fs::path p = file("shape.h5");
  {
    Id f(H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
    Id particles(make_group(f, "particles"));
    Id all(make_group(particles, "all"));
    Id position(make_group(all, "position"));
    const double x[2][3][5] = {};
    put_dataset(position, "value", H5T_NATIVE_DOUBLE, {2, 3, 5}, x);
    const std::int64_t steps[2] = {0, 1};
    put_dataset(position, "step", H5T_NATIVE_INT64, {2}, steps);
  }
  const std::string msg = test::input_error_of([&] { FrameReader r(p); });
  EXPECT_NE(msg.find(p.string() + ": /particles/all/position/value: expected positions of shape"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("got [3, 5]"), std::string::npos) << msg;
}

TEST_F(FrameStore, FileWithoutParticlesIsAnInputError) {
  const fs::path p = file("empty.h5");
  { Id created(H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)); }
  const std::string msg = test::input_error_of([&] { FrameReader r(p); });
  EXPECT_EQ(msg, p.string() + ": /particles: missing (not an H5MD file with particles)");
}

// Grows (or shrinks) a dataset along its frame axis; new rows hold the fill value.
void set_rows(hid_t file, const std::string& path, hsize_t rows) {
  Id ds(H5Dopen2(file, path.c_str(), H5P_DEFAULT));
  Id space(H5Dget_space(ds));
  hsize_t dims[4];
  const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
  ASSERT_GT(rank, 0) << path;
  dims[0] = rows;
  ASSERT_GE(H5Dset_extent(ds, dims), 0) << path;
}

// The mark close() sets on a file its writer finished.
void mark_complete(hid_t file, int complete) {
  Id group(H5Gopen2(file, "/granpipe", H5P_DEFAULT));
  Id attr(H5Aopen(group, "complete", H5P_DEFAULT));
  ASSERT_GE(H5Awrite(attr, H5T_NATIVE_INT, &complete), 0);
}

// A complete flag of 2 or -1 read as "unfinished": the file's short elements then cut
// frames off with the warning meant for a killed writer.
TEST_F(FrameStore, ACompleteFlagOtherThanZeroOrOneIsRefused) {
  const Optional none{false, false, false, false};
  for (const int flag : {2, -1}) {
    const fs::path p = write("flag" + std::to_string(flag) + ".h5", 3, 2, 4, none);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      mark_complete(f, flag);
    }
    EXPECT_EQ(reader_error(p),
              "/granpipe@complete: expected 0 (the writer never finished) or "
              "1, got " +
                  std::to_string(flag) + " (damaged file)");
  }
}

TEST_F(FrameStore, CountsOnlyFramesPresentInEveryDatasetOfAnUnfinishedFile) {
  // What a writer killed inside a frame can leave: some datasets a row ahead.
  const Optional none{false, false, false, false};
  const fs::path p = write("uneven.h5", 3, 2, 4, none);
  {
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    mark_complete(f, 0);
    set_rows(f, "/particles/all/position/value", 4);
    set_rows(f, "/granpipe/container/lo", 4);
  }
  EXPECT_EQ(FrameReader(p).frames(), 3);
  {
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    set_rows(f, "/particles/all/radius/value", 2);
  }
  FrameReader r(p);
  ASSERT_EQ(r.frames(), 2);
  expect_same_frame(make_frame(1, 2, 4, none), r.read(1));
}

// In a finished file every element holds every frame: one short of the positions read as
// fewer frames, exit 0.
TEST_F(FrameStore, AnElementShortOfTheFramesOfAFinishedFileIsRefused) {
  const Optional none{false, false, false, false};
  for (const char* path : {"/particles/all/radius/value", "/granpipe/container/lo",
                           "/particles/all/box/edges/value"}) {
    const fs::path p = write("short.h5", 3, 2, 4, none);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      set_rows(f, path, 2);
    }
    EXPECT_EQ(reader_error(p), std::string(path) +
                                   ": expected the 3 frames of the positions in a complete "
                                   "file, got 2 (damaged file)");
    fs::remove(p);
  }
  // Positions shorter than their clock (and the rest), or a clock shorter than them.
  for (const auto& [path, values, steps] : {std::tuple{"/particles/all/position/value", 2, 3},
                                            {"/particles/all/position/step", 3, 2}}) {
    const fs::path p = write("short_clock.h5", 3, 2, 4, none);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      set_rows(f, path, 2);
    }
    EXPECT_EQ(reader_error(p), "/particles/all/position/step: expected a row for each of the " +
                                   std::to_string(values) +
                                   " samples of /particles/all/position/value, got " +
                                   std::to_string(steps) + " (damaged file)");
    fs::remove(p);
  }
}

TEST_F(FrameStore, RowsWhoseStepWasNeverWrittenAreNotFrames) {
  // Every dataset holds a fourth row, but the step that commits it was never written.
  const Optional none{false, false, false, false};
  const fs::path p = write("uncommitted.h5", 3, 3, 4, none);
  {
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    mark_complete(f, 0);
    for (const char* path :
         {"/particles/all/position/value", "/particles/all/position/step",
          "/particles/all/position/time", "/particles/all/species/value", "/particles/all/id/value",
          "/particles/all/box/edges/value", "/particles/all/radius/value", "/observables/tap/value",
          "/observables/amplitude/value", "/granpipe/container/shape", "/granpipe/container/lo",
          "/granpipe/container/hi", "/granpipe/container/boundary",
          "/granpipe/container/cylinder_radius", "/granpipe/container/cylinder_center",
          "/granpipe/container/wall_offset", "/granpipe/container/wall_velocity"}) {
      set_rows(f, path, 4);
    }
  }
  {
    FrameReader r(p);
    EXPECT_EQ(r.frames(), 3);
    expect_same_frame(make_frame(2, 3, 4, none), r.read(2));
  }
  // Finished, the file has no unwritten frame: a step of INT64_MIN (the writer's mark) in
  // it is damage, not the end of the frames.
  {
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    mark_complete(f, 1);
  }
  EXPECT_EQ(reader_error(p),
            "/particles/all/position/value: frame 3: expected the step of a written frame in a "
            "complete file, got none (damaged file)");
}

// ---- Damaged and missing files ----

TEST_F(FrameStore, MissingFileIsAnInputError) {
  const fs::path p = file("nowhere.h5");
  EXPECT_EQ(test::input_error_of([&] { FrameReader r(p); }), p.string() + ": no such file");
}

// A FIFO without a writer: opening it waited for one forever (granpipe inspect hung).
TEST_F(FrameStore, APipeIsRefusedWithoutWaitingOnIt) {
  const fs::path p = file("pipe.h5");
  ASSERT_EQ(mkfifo(p.c_str(), 0600), 0);
  EXPECT_EQ(test::input_error_of([&] { FrameReader r(p); }),
            p.string() + ": expected an HDF5 file, got no regular file (a pipe, socket or device)");
}

TEST_F(FrameStore, NonHdf5FileIsAnInputError) {
  const fs::path p = file("notes.h5");
  std::ofstream(p) << "position: 1 2 3\n";
  const std::string msg = test::input_error_of([&] { FrameReader r(p); });
  EXPECT_EQ(msg, p.string() + ": not an HDF5 file (no HDF5 signature)");
}

TEST_F(FrameStore, TruncatedFileIsAnInputError) {
  const fs::path good = write("good.h5", 6, 3, 50);
  const fs::path cut = file("cut.h5");
  fs::copy_file(good, cut);
  fs::resize_file(cut, fs::file_size(good) / 2);
  const std::string msg = test::input_error_of([&] { FrameReader r(cut); });
  EXPECT_EQ(msg, cut.string() + ": not a readable HDF5 file (truncated or corrupt)");
}

// A run killed before it closed its frames file leaves the file marked open for writing,
// which HDF5 refuses to open: the message says so and what clears the mark.
TEST_F(FrameStore, FileLeftOpenByAKilledWriterSaysHowToClearIt) {
  const fs::path p = write("left_open.h5", 6, 3, 2);
  const pid_t child = fork();
  if (child == 0) {  // opens the file for writing and ends without closing it
    const hid_t f = H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    _exit(f >= 0 && H5Fflush(f, H5F_SCOPE_GLOBAL) >= 0 ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(test::input_error_of([&] { FrameReader r(p); }),
            p.string() +
                ": expected an HDF5 file its writer closed, found one still marked open for "
                "writing (a run killed before it closed the file, or one writing it now); if "
                "none writes it, `h5clear -s " +
                p.string() + "` clears the mark and its frames can be read");
}

// A chunked dataset of `dims`, of which only `written` leading elements are written
// (zeros); `deflate` compresses it.
void put_chunked(hid_t loc, const char* name, std::vector<hsize_t> dims, std::vector<hsize_t> chunk,
                 hsize_t written, bool deflate = false) {
  Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  Id dcpl(H5Pcreate(H5P_DATASET_CREATE));
  H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data());
  if (deflate) H5Pset_deflate(dcpl, 9);
  Id ds(H5Dcreate2(loc, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT));
  if (written == 0) return;
  const std::vector<double> zeros(written, 0.0);
  Id memory(H5Screate_simple(1, &written, nullptr));
  H5Dwrite(ds, H5T_NATIVE_DOUBLE, memory, H5S_ALL, H5P_DEFAULT, zeros.data());
}

// An H5MD file of one particles group without a box whose positions `position` makes.
template <class F>
void write_positions(const fs::path& p, F position) {
  Id f(H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  Id particles(make_group(f, "particles"));
  Id all(make_group(particles, "all"));
  Id box(make_group(all, "box"));
  put_string_attribute(box, "boundary", {"none", "none", "none"});
  Id group(make_group(all, "position"));
  const std::int64_t step = 1;
  put_dataset(group, "step", H5T_NATIVE_INT64, {}, &step);
  position(group);
}

// A compressed file may declare far more than it stores: 4e6 particles in a few hundred kB
// of zeros. Under a memory limit below one frame, reading it ran out of memory (a line
// naming no file); it is refused naming the dataset.
TEST_F(FrameStore, AFrameLargerThanTheMemoryLeftIsRefusedNamingTheDataset) {
  const fs::path p = file("declares_much.h5");
  write_positions(p, [](hid_t group) {
    constexpr hsize_t kParticles = 4000000;
    const hsize_t dims[3] = {1, kParticles, 3}, chunk[3] = {1, kParticles / 8, 3};
    Id space(H5Screate_simple(3, dims, nullptr));
    Id dcpl(H5Pcreate(H5P_DATASET_CREATE));
    H5Pset_chunk(dcpl, 3, chunk);
    H5Pset_deflate(dcpl, 9);
    Id value(H5Dcreate2(group, "value", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT));
    const std::vector<double> zeros(kParticles * 3, 0.0);
    H5Dwrite(value, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data());
  });
  int pipe_ends[2];
  ASSERT_EQ(pipe(pipe_ends), 0);
  const pid_t child = fork();
  if (child == 0) {  // 50 MB more than it holds: less than the frame's 272 MB
    std::ifstream statm("/proc/self/statm");
    long pages = 0;
    statm >> pages;
    const rlim_t size = static_cast<rlim_t>(pages) * static_cast<rlim_t>(sysconf(_SC_PAGESIZE));
    const rlimit limit{size + 50000000, size + 50000000};
    if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(3);
    const std::string m = test::input_error_of([&] { FrameReader r(p); });
    const ssize_t written = ::write(pipe_ends[1], m.data(), m.size());
    _exit(written == static_cast<ssize_t>(m.size()) ? 0 : 4);
  }
  close(pipe_ends[1]);
  std::string message;
  char buf[512];
  for (ssize_t n; (n = read(pipe_ends[0], buf, sizeof buf)) > 0;) message.append(buf, n);
  close(pipe_ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  const std::string expected = p.string() +
                               ": /particles/all/position/value: a frame of 4000000 particles "
                               "(68 bytes each): 0.272 GB needed, this machine (or the process's "
                               "memory limit) has ";
  EXPECT_EQ(message.substr(0, expected.size()), expected) << message;
}

// HDF5 reads what was never written as the fill value: an 8 KB file declaring 5e7
// particles took gigabytes before it was found to hold none.
TEST_F(FrameStore, DeclaredDataTheFileDoesNotStoreIsRefusedBeforeReading) {
  const fs::path p = file("unstored.h5");
  write_positions(p, [](hid_t g) { put_chunked(g, "value", {1, 50000000, 3}, {1, 100000, 3}, 0); });
  ASSERT_LT(fs::file_size(p), 10000u);
  EXPECT_EQ(test::input_error_of([&] { FrameReader r(p); }),
            p.string() +
                ": /particles/all/position/value: expected at most 1.68e+07 bytes of data for "
                "the 0 bytes stored in the file, got shape [1, 50000000, 3] (1.2e+09 bytes; "
                "damaged or crafted file)");
}

// Rows of zero particles take no bytes, but a fixed clock would be a step per row.
TEST_F(FrameStore, DeclaredRowsTheFileDoesNotStoreAreRefused) {
  const fs::path p = file("unstored_rows.h5");
  write_positions(p, [](hid_t g) {
    put_chunked(g, "value", {1000000000000, 0, 3}, {1000, 1, 3}, 0);
  });
  EXPECT_EQ(test::input_error_of([&] { FrameReader r(p); }),
            p.string() +
                ": /particles/all/position/value: expected at most 1.68e+07 rows for the 0 bytes "
                "stored in the file, got shape [1000000000000, 0, 3] (damaged or crafted file)");
}

// 24 MB of zeros deflate to a few kilobytes, and are data the file does hold.
TEST_F(FrameStore, CompressedDataIsStoredData) {
  const fs::path p = file("deflated.h5");
  write_positions(p, [](hid_t g) {
    put_chunked(g, "value", {1, 1000000, 3}, {1, 100000, 3}, 3000000, true);
  });
  ASSERT_LT(fs::file_size(p), 1000000u);
  FrameReader r(p);
  EXPECT_EQ(r.info().particles, 1000000);
}

// Overwrites row `row` of a 1-D integer dataset.
void put_row(hid_t file, const std::string& path, hsize_t row, std::int64_t value) {
  Id ds(H5Dopen2(file, path.c_str(), H5P_DEFAULT));
  Id space(H5Dget_space(ds));
  const hsize_t one = 1;
  H5Sselect_hyperslab(space, H5S_SELECT_SET, &row, nullptr, &one, nullptr);
  Id memory(H5Screate_simple(1, &one, nullptr));
  ASSERT_GE(H5Dwrite(ds, H5T_NATIVE_INT64, memory, space, H5P_DEFAULT, &value), 0) << path;
}

// A frame's contact count is what the reader allocates: checked against the arrays first.
TEST_F(FrameStore, ContactsOutsideTheContactArraysAreRefused) {
  const fs::path good = write("contacts.h5", 3, 3, 5);  // 1, 6 and 0 contacts: 7 rows
  for (const auto& [offset, count] : {std::pair<std::int64_t, std::int64_t>{1, 1LL << 62},
                                      {1, -1},
                                      {-6, 6},
                                      {1LL << 62, 1LL << 62}}) {
    const fs::path p = file("bad_contacts.h5");
    fs::copy_file(good, p, fs::copy_options::overwrite_existing);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      put_row(f, "/granpipe/contacts/offset", 1, offset);
      put_row(f, "/granpipe/contacts/count", 1, count);
    }
    EXPECT_EQ(test::input_error_of([&] { FrameReader r(p); }),
              p.string() +
                  ": /granpipe/contacts: frame 1: expected rows within the 7 contact rows, "
                  "got offset " +
                  std::to_string(offset) + " and count " + std::to_string(count) +
                  " (damaged file)");
  }
}

// Frame 1's offset pointed back at frame 0's row (read as its own contacts), or a count cut
// short dropped contacts, exit 0.
TEST_F(FrameStore, ContactsOutOfTheirFramesOrderInAFinishedFileAreRefused) {
  const fs::path good = write("contacts.h5", 3, 3, 5);  // 1, 6 and 0 contacts: 7 rows
  auto damaged = [&](std::int64_t offset, std::int64_t count) {
    const fs::path p = file("out_of_order.h5");
    fs::copy_file(good, p, fs::copy_options::overwrite_existing);
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    put_row(f, "/granpipe/contacts/offset", 1, offset);
    put_row(f, "/granpipe/contacts/count", 1, count);
    return p;
  };
  EXPECT_EQ(reader_error(damaged(0, 1)),
            "/granpipe/contacts/offset: frame 1: expected offset 1 (after the rows of the frames "
            "before), got 0 (damaged file)");
  EXPECT_EQ(reader_error(damaged(1, 5)),
            "/granpipe/contacts/offset: frame 2: expected offset 6 (after the rows of the frames "
            "before), got 7 (damaged file)");
}

// A partner out of range would read as a wall (j <= -2) or a particle that is not there:
// only particle rows and the wall codes (-2 to -8) are contacts.
TEST_F(FrameStore, ContactPartnersOutOfRangeAreRefusedNamingTheRow) {
  const fs::path good = write("contacts.h5", 3, 3, 5);  // frame 1: rows 1 to 6
  const std::string where = ": row 3 (frame 1, contact 2): expected a particle index in [0, 5)";
  for (const auto& [column, value] : {std::pair<std::string, std::int64_t>{"j", -100},
                                      {"j", -9},
                                      {"j", 5},
                                      {"j", 2},
                                      {"j", -1},
                                      {"i", -6},
                                      {"i", 5}}) {
    const fs::path p = file("bad_partner.h5");
    fs::copy_file(good, p, fs::copy_options::overwrite_existing);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      put_row(f, "/granpipe/contacts/" + column, 3, value);
    }
    const FrameReader r(p);
    EXPECT_NO_THROW(r.read(0));
    const std::string expected =
        column == "i"
            ? where + ", got " + std::to_string(value)
            : where + " other than i (2) or a wall code -2 (x_low) to -8 (cylinder), got " +
                  std::to_string(value);
    EXPECT_EQ(test::input_error_of([&] { r.read(1); }),
              p.string() + ": /granpipe/contacts/" + column + expected);
  }
}

// Two particles of one id would read as one in every analysis that follows a particle by
// its id (and as two in every count): a file holding them is refused, naming the first id
// met again.
TEST_F(FrameStore, ParticleIdsGivenTwiceInAFrameAreRefused) {
  const fs::path p = file("twice.h5");
  {
    FrameWriter w(p, "{}");
    Frame f = make_frame(0, 3, 4);
    f.id() << 5, 7, 7, 5;
    w.append(f);
    w.close();
  }
  EXPECT_EQ(test::input_error_of([&] { FrameReader(p).read(0); }),
            p.string() +
                ": /particles/all/id/value: frame 0: expected each particle id once, got id 7 "
                "again (particles 1 and 2)");
}

// Overwrites entry [row][column] of a 2-D real dataset.
void put_real(hid_t file, const std::string& path, hsize_t row, hsize_t column, double value) {
  Id ds(H5Dopen2(file, path.c_str(), H5P_DEFAULT));
  Id space(H5Dget_space(ds));
  const hsize_t start[2] = {row, column}, one[2] = {1, 1};
  H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, one, nullptr);
  Id memory(H5Screate_simple(2, one, nullptr));
  ASSERT_GE(H5Dwrite(ds, H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, &value), 0) << path;
}

// Other tools read the box from box/edges, granpipe from its container: a file where the
// two disagree (edited by one of them) would give two tools two packing fractions.
TEST_F(FrameStore, BoxEdgesThatDisagreeWithTheContainerAreRefused) {
  const fs::path good = write("box.h5", 2, 3, 5);  // frame 1: y from -2.02 to 5
  const std::string edges = "/particles/all/box/edges/value";
  const fs::path p = file("edited_box.h5");
  for (const double edge : {7.02 * (1.0 + 1e-12), 7.5}) {
    fs::copy_file(good, p, fs::copy_options::overwrite_existing);
    {
      Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
      put_real(f, edges, 1, 1, edge);
    }
    const FrameReader r(p);
    if (edge < 7.1) {
      EXPECT_NO_THROW(r.read(1));  // within rounding: agrees
      continue;
    }
    EXPECT_NO_THROW(r.read(0));
    EXPECT_EQ(test::input_error_of([&] { r.read(1); }),
              p.string() + ": " + edges +
                  ": frame 1: expected the container's edge along y (/granpipe/container hi - "
                  "lo), 7.02, got 7.5");
  }
}

// ---- Crash safety ----

// A child appends frames for ever, telling the parent after each one; the parent kills
// it with SIGKILL (no chance to clean up) at an arbitrary point of a later frame, after
// a delay of up to 2 ms so that some kills land inside a flush. A torn write is rare (it
// was one kill in 250 under disk load before paged file space): GRANPIPE_KILLS=2000 runs
// the stress of docs/notes/killed-writer.md.
TEST_F(FrameStore, EveryFrameOfAKilledWriterReadsBackExactly) {
  constexpr int kDim = 3;
  constexpr Eigen::Index kParticles = 300;
  const char* kills_asked = std::getenv("GRANPIPE_KILLS");
  const int kills = kills_asked ? std::atoi(kills_asked) : 6;
  for (int attempt = 0; attempt < kills; ++attempt) {
    const int kill_after = 1 + (attempt * 4) % 9;
    const useconds_t delay = static_cast<useconds_t>((attempt * 397) % 2000);
    SCOPED_TRACE("kill " + std::to_string(attempt) + " after " + std::to_string(kill_after) +
                 " frames and " + std::to_string(delay) + " us");
    const fs::path p = file("killed" + std::to_string(attempt) + ".h5");
    int pipe_fd[2];
    ASSERT_EQ(pipe(pipe_fd), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      close(pipe_fd[0]);
      try {
        FrameWriter w(p, "{}");
        for (long k = 0;; ++k) {
          w.append(make_frame(k, kDim, kParticles));
          const char done = 1;
          if (::write(pipe_fd[1], &done, 1) != 1) _exit(3);
        }
      } catch (...) {
        _exit(2);
      }
    }
    close(pipe_fd[1]);
    for (int n = 0; n < kill_after; ++n) {
      char done = 0;
      ASSERT_EQ(::read(pipe_fd[0], &done, 1), 1) << "the writer died on its own";
    }
    usleep(delay);
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    close(pipe_fd[0]);
    ASSERT_TRUE(WIFSIGNALED(status));

    FrameReader r(p);
    EXPECT_FALSE(r.info().complete);
    EXPECT_GE(r.frames(), kill_after);
    for (long k = 0; k < r.frames(); ++k) {
      SCOPED_TRACE("frame " + std::to_string(k));
      expect_same_frame(make_frame(k, kDim, kParticles), r.read(k));
    }
    fs::remove(p);
  }
}

}  // namespace

// Files of frames layout 1.x (granpipe before core v2) are refused in one line that names
// the version, not misread.
TEST_F(FrameStore, AFileOfAnotherLayoutVersionIsRefusedNamingIt) {
  const Optional none{false, false, false, false};
  const fs::path p = write("layout1.h5", 2, 3, 4, none);
  {
    Id f(H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    Id ext(H5Gopen2(f, "/granpipe", H5P_DEFAULT));
    H5Adelete(ext, "version");
    put_int_attribute(ext, "version", {1, 0}, false);
  }
  EXPECT_EQ(test::input_error_of([&] { FrameReader r(p); }),
            p.string() +
                ": /granpipe@version: expected frames layout 2.x, got 1.x (written by "
                "another granpipe version; docs/file-format.md lists the layouts)");
}
