// The lammps_dump source on dumps written here: any column order, plain, scaled and
// unwrapped positions, radius or diameter, rows sorted by id, many snapshots selected as
// the h5md source selects frames, gzip, a file cut inside its last snapshot, kept columns;
// and every refusal as one line naming the file, the timestep and the line.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "lammps_dump_source.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

struct Atom {
  std::int64_t id;
  int type;
  Eigen::Vector3d x, v;
  double radius;
};

// Four atoms in the box [0, 4] x [-1, 3] x [0, 10], periodic along x and y, listed out of
// id order. Their coordinates are exact binary fractions, so that scaling by the box is exact
// but for the one atom at 1/3 of its sides.
std::vector<Atom> atoms() {
  return {{3, 1, {0.5, 0.25, 0.5}, {1, 2, 3}, 0.5},
          {1, 2, {3.75, 2.5, 1.0}, {-1, 0, 0.5}, 0.25},
          {10, 1, {4.0 / 3.0, 1.0 / 3.0, 5.5}, {0, 0, -2}, 0.3},
          {2, 1, {2.0, -0.5, 2.0}, {0.125, 0, 0}, 0.5}};
}

const Eigen::Vector3d kLo(0, -1, 0), kHi(4, 3, 10);

std::string number(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

// One value of an atom for a dump column: x as written, xs scaled, xu unwrapped (moved
// by `image` periodic boxes), xsu both, radius or diameter, vx..., id and type.
using Column = std::function<std::string(const Atom&)>;

Column column(const std::string& name, int image = 0) {
  auto axis = [](char c) { return c - 'x'; };
  auto length = [](int a) { return kHi[a] - kLo[a]; };
  const int a = axis(name[0]);
  const double shift = a < 2 ? image * length(a) : 0.0;  // z is not periodic
  if (name == "id") return [](const Atom& t) { return std::to_string(t.id); };
  if (name == "type") return [](const Atom& t) { return std::to_string(t.type); };
  if (name == "radius") return [](const Atom& t) { return number(t.radius); };
  if (name == "diameter") return [](const Atom& t) { return number(2 * t.radius); };
  if (name[0] == 'v') return [=](const Atom& t) { return number(t.v[name[1] - 'x']); };
  if (name.size() == 1) return [=](const Atom& t) { return number(t.x[a]); };
  if (name == std::string(1, name[0]) + "u")
    return [=](const Atom& t) { return number(t.x[a] + shift); };
  const int images = name.size() == 3 && a < 2 ? image : 0;  // xsu, ysu
  return [=](const Atom& t) { return number((t.x[a] - kLo[a]) / length(a) + images); };
}

// A snapshot of `list` with these columns; `image` moves unwrapped positions.
std::string snapshot(std::int64_t step, const std::vector<Atom>& list,
                     const std::vector<std::string>& names, int image = 0,
                     const std::string& flags = "pp pp ff") {
  std::ostringstream s;
  s << "ITEM: TIMESTEP\n" << step << "\nITEM: NUMBER OF ATOMS\n" << list.size() << "\n";
  s << "ITEM: BOX BOUNDS " << flags << "\n";
  for (int a = 0; a < 3; ++a) s << number(kLo[a]) << " " << number(kHi[a]) << "\n";
  s << "ITEM: ATOMS";
  for (const auto& n : names) s << " " << n;
  s << "\n";
  for (const Atom& t : list) {
    for (std::size_t k = 0; k < names.size(); ++k)
      s << (k ? " " : "") << column(names[k], image)(t);
    s << "\n";
  }
  return s.str();
}

const std::vector<std::string> kPlain{"id", "type", "x", "y", "z", "radius", "vx", "vy", "vz"};

class LammpsDump : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ =
        fs::temp_directory_path() / ("granpipe_dump_" + std::to_string(getpid()) + "_" + t->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& content, const std::string& name = "atoms.dump") {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  fs::path write_gz(const std::string& content, const std::string& name = "atoms.dump.gz") {
    const fs::path p = dir_ / name;
    gzFile f = gzopen(p.c_str(), "wb");
    gzwrite(f, content.data(), static_cast<unsigned>(content.size()));
    gzclose(f);
    return p;
  }

  std::unique_ptr<lammps_dump::LammpsDumpSource> source(const fs::path& file,
                                                        nlohmann::json params = {}) {
    params["file"] = file.string();
    harness_ = test::make_context("lammps_dump", params);
    harness_->keep_log();
    return std::make_unique<lammps_dump::LammpsDumpSource>(*harness_);
  }
  std::vector<Frame> frames(const fs::path& file, nlohmann::json params = {}) {
    auto s = source(file, std::move(params));
    std::vector<Frame> out;
    for (Frame f; s->next(f);) out.push_back(f);
    return out;
  }
  Frame frame(const std::string& content, nlohmann::json params = {}) {
    const auto all = frames(write(content), std::move(params));
    EXPECT_EQ(all.size(), 1u);
    return all.at(0);
  }
  // The source's refusal of this file, from the file's name on, or "accepted".
  std::string refusal_of_file(const fs::path& file, nlohmann::json params = {}) {
    try {
      frames(file, std::move(params));
    } catch (const InputError& e) {
      std::string m = e.what();
      const auto at = m.find(dir_.string() + "/");
      return at == std::string::npos ? m : m.erase(at, dir_.string().size() + 1);
    }
    return "accepted";
  }
  std::string refusal(const std::string& content, nlohmann::json params = {}) {
    return refusal_of_file(write(content), std::move(params));
  }

  fs::path dir_;
  std::unique_ptr<test::PluginHarness> harness_;
};

// The frame of atoms(): rows in id order 1, 2, 3, 10.
void expect_the_atoms(const Frame& f, double tolerance = 0.0) {
  ASSERT_EQ(f.size(), 4);
  const std::vector<std::size_t> by_id{1, 3, 0, 2};  // rows of atoms() in id order
  const std::vector<Atom> list = atoms();
  for (Eigen::Index k = 0; k < 4; ++k) {
    const Atom& t = list[by_id[static_cast<std::size_t>(k)]];
    EXPECT_EQ(f.id()[k], t.id);
    EXPECT_EQ(f.species()[k], t.type - 1);
    EXPECT_EQ(f.radius()[k], t.radius);
    for (int a = 0; a < 3; ++a) {
      // y = -0.5 lies in [-1, 3): no wrapping moves it.
      EXPECT_NEAR(f.position()(k, a), t.x[a], tolerance) << "id " << t.id << " axis " << a;
    }
  }
}

}  // namespace

TEST_F(LammpsDump, ReadsASnapshotInIdOrder) {
  const Frame f = frame(snapshot(500, atoms(), kPlain));
  expect_the_atoms(f);
  EXPECT_EQ(f.step, 500);
  EXPECT_TRUE(std::isnan(f.time));                    // no ITEM: TIME and no dt
  EXPECT_EQ(f.table<double>("velocity")(0, 2), 0.5);  // id 1
  EXPECT_EQ(f.table<double>("velocity")(2, 1), 2.0);  // id 3
  // The box's periodic sides from BOX BOUNDS; z: the stated base and open top.
  const Container& c = f.container;
  EXPECT_EQ(c.shape, ContainerShape::Box);
  EXPECT_TRUE(c.periodic(0) && c.periodic(1));
  EXPECT_EQ(c.lo[1], -1.0);
  EXPECT_EQ(c.hi[0], 4.0);
  EXPECT_EQ(c.boundary[2][0], Boundary::Wall);
  EXPECT_EQ(c.boundary[2][1], Boundary::Open);
  EXPECT_EQ(c.hi[2], 100.0);
}

TEST_F(LammpsDump, ColumnOrderAndRowOrderDoNotMatter) {
  const Frame plain = frame(snapshot(0, atoms(), kPlain));
  std::vector<Atom> reversed = atoms();
  std::reverse(reversed.begin(), reversed.end());
  const Frame shuffled =
      frame(snapshot(0, reversed, {"vz", "radius", "z", "id", "x", "vy", "type", "y", "vx"}));
  expect_the_atoms(shuffled);
  EXPECT_TRUE((shuffled.position() == plain.position()).all());
  EXPECT_TRUE((shuffled.table<double>("velocity") == plain.table<double>("velocity")).all());
}

TEST_F(LammpsDump, ScaledAndUnwrappedPositionsAreThePlainOnes) {
  const std::vector<std::string> id_type_radius{"id", "type", "radius"};
  auto with = [&](std::vector<std::string> positions) {
    positions.insert(positions.begin(), id_type_radius.begin(), id_type_radius.end());
    return positions;
  };
  expect_the_atoms(frame(snapshot(0, atoms(), with({"xs", "ys", "zs"}))), 1e-12);
  for (int image : {-2, 1, 3}) {
    expect_the_atoms(frame(snapshot(0, atoms(), with({"xu", "yu", "zu"}), image)), 1e-12);
    expect_the_atoms(frame(snapshot(0, atoms(), with({"xsu", "ysu", "zsu"}), image)), 1e-12);
  }
  // Kinds mixed per axis, as dump custom allows.
  expect_the_atoms(frame(snapshot(0, atoms(), with({"xs", "yu", "z"}), 1)), 1e-12);
  // 2^27 periods away a position wrapped keeps under half its digits (x = 1e300 wrapped to
  // an arbitrary place and was refused as an overlap of two other atoms, "line 1").
  EXPECT_EQ(refusal(snapshot(0, atoms(), with({"xu", "yu", "zu"}), 134217728)),
            "atoms.dump: timestep 0, line 11: expected a position within 2^26 periods of the "
            "box along x (wrapped into it, one farther keeps under half its digits), got "
            "5.36871e+08");
}

TEST_F(LammpsDump, PlainPositionsAreWrappedIntoPeriodicSides) {
  std::vector<Atom> list = atoms();
  list[1].x[0] = 3.75 + 4.0;  // id 1, one box along x away
  const Frame f = frame(snapshot(0, list, kPlain));
  EXPECT_EQ(f.position()(0, 0), 3.75);
}

TEST_F(LammpsDump, ADiameterColumnGivesHalfOfIt) {
  expect_the_atoms(frame(snapshot(0, atoms(), {"id", "type", "x", "y", "z", "diameter"})));
}

// Both columns: the radius was read and the diameter, saying something else, ignored.
TEST_F(LammpsDump, ARadiusAndADiameterColumnTogetherAreRefused) {
  EXPECT_EQ(refusal(snapshot(0, atoms(), {"id", "type", "x", "y", "z", "radius", "diameter"})),
            "atoms.dump: timestep 0, line 9: expected a radius or a diameter column, got both "
            "(\"id type x y z radius diameter\")");
}

TEST_F(LammpsDump, WithoutARadiusColumnTheRadiusParameterIsEveryAtoms) {
  const auto columns = std::vector<std::string>{"id", "type", "xs", "ys", "zs"};  // dump atom
  const Frame f = frame(snapshot(0, atoms(), columns), {{"radius", 0.25}});
  EXPECT_TRUE((f.radius() == 0.25).all());
  EXPECT_EQ(refusal(snapshot(0, atoms(), columns)),
            "atoms.dump: timestep 0, line 9: expected a radius or diameter column (or "
            "params.radius for a dump without one), got none");
  EXPECT_EQ(refusal(snapshot(0, atoms(), kPlain), {{"radius", 0.25}}),
            "params.radius: expected 0 for a dump with a radius column (atoms.dump), got 0.25");
}

TEST_F(LammpsDump, EachSnapshotIsAFrameSelectedAsTheH5mdSourceSelects) {
  std::string text;
  for (int k = 0; k < 5; ++k) text += snapshot(1000 * k, atoms(), kPlain);
  const fs::path file = write(text);
  auto steps = [&](nlohmann::json params) {
    std::vector<std::int64_t> out;
    for (const Frame& f : frames(file, std::move(params))) out.push_back(f.step);
    return out;
  };
  using Steps = std::vector<std::int64_t>;
  EXPECT_EQ(steps({}), (Steps{0, 1000, 2000, 3000, 4000}));
  EXPECT_EQ(steps({{"first", 1}, {"stride", 2}}), (Steps{1000, 3000}));
  EXPECT_EQ(steps({{"first", 1}, {"last", 2}}), (Steps{1000, 2000}));
  EXPECT_EQ(source(file, {{"stride", 2}})->work().total, 3.0);
  EXPECT_EQ(refusal_of_file(file, {{"first", 5}}),
            "params.first: expected a frame index below 5, got 5 (atoms.dump holds 5 snapshots)");
  EXPECT_EQ(refusal_of_file(file, {{"first", 3}, {"last", 2}}),
            "params.last: expected -1 or an index >= first (3), got 2");
}

TEST_F(LammpsDump, TheTimeIsItemTimeOrTheStepTimesDt) {
  const std::string text = snapshot(300, atoms(), kPlain);
  EXPECT_EQ(frame(text, {{"dt", 0.5}}).time, 150.0);
  EXPECT_TRUE(harness_->logged_lines().empty());
  // Neither: NaN in every time column of the results, said once with the cure.
  EXPECT_TRUE(std::isnan(frame(text).time));
  EXPECT_EQ(harness_->logged_lines(),
            std::vector<std::string>{"warning: " + (dir_ / "atoms.dump").string() +
                                     ": the dump has no ITEM: TIME and params.dt is 0: times are "
                                     "undefined (NaN in the results); give the run's timestep as "
                                     "params.dt"});
  // dump_modify units yes, time yes: ITEM: UNITS once, ITEM: TIME in every snapshot.
  EXPECT_EQ(frame("ITEM: UNITS\nlj\nITEM: TIME\n2.75\n" + text).time, 2.75);
  // A dt beside the file's own times (LAMMPS counts them through reset_timestep and changes
  // of dt) was dropped without a word: it is said.
  EXPECT_EQ(frame("ITEM: TIME\n2.75\n" + text, {{"dt", 0.5}}).time, 2.75);
  EXPECT_EQ(harness_->logged_lines(),
            std::vector<std::string>{"warning: " + (dir_ / "atoms.dump").string() +
                                     ": params.dt is not used: the dump states its times (ITEM: "
                                     "TIME)"});
  // A dt of 1e308 gave every frame the time inf, exit 0.
  EXPECT_EQ(refusal(text, {{"dt", 1e308}}),
            "params.dt: expected a time step whose product with the dump's TIMESTEP 300 is "
            "finite, got 1e+308");
  // Times that ran down while the timesteps rose gave the intruder's lift-offs backwards,
  // exit 0.
  const std::string later = snapshot(400, atoms(), kPlain);
  EXPECT_EQ(frames(write("ITEM: TIME\n2.75\n" + text + "ITEM: TIME\n2.75\n" + later)).size(), 2u);
  EXPECT_EQ(refusal("ITEM: TIME\n2.75\n" + text + "ITEM: TIME\n2.5\n" + later),
            "atoms.dump: timestep 400, line 16: expected a time at or after 2.75 (the snapshot "
            "read before it), got 2.5");
  // A snapshot without a time between them (two dumps joined) had its time from dt, its
  // neighbours from the file, exit 0.
  EXPECT_EQ(refusal("ITEM: TIME\n2.75\n" + text + snapshot(350, atoms(), kPlain) +
                    "ITEM: TIME\n2.5\n" + later),
            "atoms.dump: timestep 350, line 16: expected ITEM: TIME, as the snapshots read before "
            "it, got none");
  EXPECT_EQ(refusal(text + "ITEM: TIME\n2.5\n" + later, {{"dt", 0.01}}),
            "atoms.dump: timestep 400, line 14: expected no ITEM: TIME, as none of the snapshots "
            "read before it, got one");
}

TEST_F(LammpsDump, AGzipFileReadsAsThePlainOne) {
  const std::string text = snapshot(0, atoms(), kPlain) + snapshot(10, atoms(), kPlain);
  const auto plain = frames(write(text));
  const auto gz = frames(write_gz(text));
  ASSERT_EQ(gz.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(gz[k].step, plain[k].step);
    EXPECT_TRUE((gz[k].position() == plain[k].position()).all());
    EXPECT_TRUE((gz[k].radius() == plain[k].radius()).all());
    EXPECT_TRUE((gz[k].id() == plain[k].id()).all());
  }
}

TEST_F(LammpsDump, TrailingSpacesBlankLinesAndCarriageReturnsAreTolerated) {
  std::string text = snapshot(0, atoms(), kPlain);
  std::string spaced;
  for (char c : text) spaced += c == '\n' ? std::string("  \t\r\n") : std::string(1, c);
  expect_the_atoms(frame(spaced + "\n\n  \n"));
}

TEST_F(LammpsDump, AFileCutInsideItsLastSnapshotGivesTheCompleteOnesWithAWarning) {
  const std::string two = snapshot(0, atoms(), kPlain) + snapshot(10, atoms(), kPlain);
  const std::string third = snapshot(20, atoms(), kPlain);
  const fs::path file = write(two + third.substr(0, third.size() - 20));  // inside an atom line
  EXPECT_EQ(frames(file, {{"dt", 0.5}}).size(), 2u);
  const auto log = harness_->logged_lines();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find(file.string() +
                        ": the file ends inside the snapshot of timestep 20 (from line 27), as "
                        "when its writer is stopped: reading the 2 complete snapshots before it"),
            std::string::npos)
      << log[0];
  // Cut inside the header, before its timestep.
  write(two + "ITEM: TIMESTEP\n");
  EXPECT_EQ(frames(file).size(), 2u);
  EXPECT_NE(harness_->logged_lines().at(0).find("the file ends inside the snapshot from line 27"),
            std::string::npos);
  EXPECT_EQ(refusal(third.substr(0, 30)),
            "atoms.dump: expected a complete snapshot, got none: the file ends inside the "
            "snapshot of timestep 20 (from line 1)");
}

// A gzip stream cut right after the second snapshot: both are read, and the warning says
// that the compressed data end early.
TEST_F(LammpsDump, AGzipFileCutShortIsReadToTheCutWithAWarning) {
  const fs::path file = dir_ / "cut.dump.gz";
  const std::string two = snapshot(0, atoms(), kPlain) + snapshot(10, atoms(), kPlain);
  gzFile f = gzopen(file.c_str(), "wb");
  gzwrite(f, two.data(), static_cast<unsigned>(two.size()));
  gzflush(f, Z_SYNC_FLUSH);
  const auto cut_at = static_cast<std::uintmax_t>(gzoffset(f));
  const std::string third = snapshot(20, atoms(), kPlain);
  gzwrite(f, third.data(), static_cast<unsigned>(third.size()));
  gzclose(f);
  fs::resize_file(file, cut_at);
  EXPECT_EQ(frames(file).size(), 2u);
  EXPECT_NE(harness_->logged_lines().at(0).find(
                "cut.dump.gz: the compressed data end early (the file was cut): reading the 2 "
                "complete snapshots before it"),
            std::string::npos);
}

// zlib passes silently over bytes after a gzip member that start no other: text appended
// to a compressed dump would be left out. Members written one after another (a dump
// appended to with gzip) are one text.
TEST_F(LammpsDump, TextAfterTheGzipDataIsRefusedAndJoinedMembersAreRead) {
  const std::string first = snapshot(0, atoms(), kPlain);
  const std::string second = snapshot(10, atoms(), kPlain);
  const fs::path file = write_gz(first + second);
  const auto compressed_bytes = fs::file_size(file);
  std::ofstream(file, std::ios::binary | std::ios::app) << snapshot(20, atoms(), kPlain);
  EXPECT_EQ(refusal_of_file(file),
            "atoms.dump.gz: expected nothing after the gzip data, got bytes that are not gzip "
            "from byte " +
                std::to_string(compressed_bytes) +
                " on (text appended to a compressed file?): decompress it, append, compress it "
                "again");

  const fs::path one = write_gz(first, "one.gz"), two = write_gz(second, "two.gz");
  const fs::path joined = dir_ / "joined.dump.gz";
  std::ofstream(joined, std::ios::binary) << std::ifstream(one, std::ios::binary).rdbuf()
                                          << std::ifstream(two, std::ios::binary).rdbuf();
  EXPECT_EQ(frames(joined).size(), 2u);
  std::ofstream(joined, std::ios::binary | std::ios::app) << "x";  // a single stray byte
  EXPECT_EQ(refusal_of_file(joined).substr(0, 70),
            "joined.dump.gz: expected nothing after the gzip data, got bytes that a");
  // Bytes whose last four are the text's length, as a one-member file's trailer ends.
  const std::string text = first + second;
  const fs::path posing = write_gz(text, "posing.dump.gz");
  std::string tail = "junk";
  for (int k = 0; k < 4; ++k) tail += static_cast<char>((text.size() >> (8 * k)) & 0xff);
  std::ofstream(posing, std::ios::binary | std::ios::app) << tail;
  EXPECT_EQ(refusal_of_file(posing).substr(0, 70),
            "posing.dump.gz: expected nothing after the gzip data, got bytes that a");
  // Zero bytes padding a file to a block size are no text (gzip ignores them too); a byte
  // after them is.
  const fs::path padded = write_gz(text, "padded.dump.gz");
  std::ofstream(padded, std::ios::binary | std::ios::app) << std::string(100000, '\0');
  EXPECT_EQ(frames(padded).size(), 2u);
  std::ofstream(padded, std::ios::binary | std::ios::app) << "ITEM";
  EXPECT_EQ(refusal_of_file(padded).substr(0, 70),
            "padded.dump.gz: expected nothing after the gzip data, got bytes that a");
}

TEST_F(LammpsDump, AGzipFileCutInItsHeaderOrCorruptIsRefusedAsSuch) {
  const fs::path file = write_gz(snapshot(0, atoms(), kPlain));
  fs::resize_file(file, 10);  // the gzip header alone
  EXPECT_EQ(refusal_of_file(file),
            "atoms.dump.gz: expected a LAMMPS dump (starting \"ITEM: TIMESTEP\"), got gzip data "
            "that end before the first line (the file was cut)");
  const fs::path corrupt = write_gz(snapshot(0, atoms(), kPlain));
  {
    std::fstream f(corrupt, std::ios::binary | std::ios::in | std::ios::out);
    f.seekp(static_cast<std::streamoff>(fs::file_size(corrupt)) - 6);  // inside the checksum
    f.put('\x5a');
  }
  EXPECT_EQ(refusal_of_file(corrupt),
            "atoms.dump.gz: the gzip data are corrupt (incorrect data check), found before its "
            "first line");
}

TEST_F(LammpsDump, OtherColumnsAreKeptUnderTheirNames) {
  auto s = source(write(
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 4\n-1 3\n0 10\n"
      "ITEM: ATOMS id type x y z radius mass c_coord[1] element\n"
      "7 1 1 1 1 0.5 0.52 6 C\n"
      "2 1 3 1 1 0.5 0.25 nan C\n"));
  const auto columns = s->content().columns;
  ASSERT_EQ(columns.size(), 2u);  // element names are text: left out
  EXPECT_EQ(columns[0].name, "mass");
  EXPECT_EQ(columns[1].name, "c_coord_1");
  EXPECT_EQ(columns[1].doc, "the dump's column c_coord[1]");
  Frame f;
  ASSERT_TRUE(s->next(f));
  EXPECT_EQ(f.get<double>("mass")[0], 0.25);               // id 2
  EXPECT_TRUE(std::isnan(f.get<double>("c_coord_1")[0]));  // undefined stays undefined
  EXPECT_EQ(f.get<double>("c_coord_1")[1], 6.0);           // id 7
}

// A column "box" passed the header and failed at the first frame's save, naming the frames
// file and not the dump.
TEST_F(LammpsDump, AColumnNamedAsTheFramesFilesBoxIsRefusedAtItsHeader) {
  EXPECT_EQ(refusal(snapshot(0, atoms(), {"id", "type", "x", "y", "z", "radius", "box"})),
            "atoms.dump: timestep 0, line 9: expected a column name granpipe can keep, got "
            "\"box\" (kept as \"box\": the name of the frames file's box)");
}

TEST_F(LammpsDump, ATriclinicBoxIsRefused) {
  std::string text = snapshot(0, atoms(), kPlain);
  text.replace(text.find("pp pp ff"), 8, "xy xz yz pp pp ff");
  EXPECT_EQ(refusal(text),
            "atoms.dump: timestep 0, line 5: expected an orthogonal box (\"ITEM: BOX BOUNDS pp "
            "pp ff\"), got a triclinic one (\"ITEM: BOX BOUNDS xy xz yz pp pp ff\"): granpipe's "
            "containers have right angles");
}

// 200 atoms stacked at one point gave a packing fraction of 1.64, exit 0.
TEST_F(LammpsDump, AtomsOverlappingBeyondMaxOverlapAreRefused) {
  std::vector<Atom> list = atoms();
  for (Atom& t : list) t.x.head<2>() *= 0.1;  // atoms 1 and 3 overlap by 0.45 of a radius
  const std::string text = snapshot(0, list, kPlain, 0, "ff ff ff");
  EXPECT_EQ(refusal(text),
            "atoms.dump: timestep 0, line 1: particles 1 and 3 overlap by 0.45049 of the smaller "
            "radius, expected at most 0.3 (params.max_overlap)");
  EXPECT_EQ(refusal(text, {{"max_overlap", 0.5}}), "accepted");
}

TEST_F(LammpsDump, AnAtomOutsideTheStatedContainerIsRefusedWithItsLine) {
  std::vector<Atom> list = atoms();
  for (Atom& t : list) t.x.head<2>() *= 0.1;  // near the axis of a cylinder of radius 2
  list[2].x = {1.9, 0, 6};                    // id 10, radius 0.3, on line 12
  const std::string text = snapshot(0, list, kPlain, 0, "ff ff ff");
  EXPECT_EQ(refusal(text, {{"max_overlap", 0.5}, {"cylinder_radius", 2.0}}),
            "atoms.dump: timestep 0, line 12: atom 10 at (1.9, 0, 6), radius 0.3: expected an "
            "overlap with the wall cylinder (radius 2 about (0, 0)) of at most 0.015 (0.05 of "
            "its radius), got 0.2 (the container of params.cylinder_radius)");
  EXPECT_EQ(
      refusal(text, {{"max_overlap", 0.5}, {"cylinder_radius", 2.0}, {"cylinder_axis", {0.2, 0}}}),
      "accepted");
  EXPECT_EQ(refusal(text, {{"max_overlap", 0.5}, {"cylinder_radius", 2.0}, {"top", 5.0}}),
            "atoms.dump: timestep 0, line 12: atom 10 at (1.9, 0, 6), radius 0.3: expected its "
            "centre inside the open side z_high (z = 5), got it 1 beyond (the container of "
            "params.top)");
  EXPECT_EQ(refusal(text, {{"side_walls", {-1, 1.5, -1, 1}}}),
            "atoms.dump: timestep 0, line 12: atom 10 at (1.9, 0, 6), radius 0.3: expected an "
            "overlap with the wall x_high (x = 1.5) of at most 0.015 (0.05 of its radius), got "
            "0.7 (the container of params.side_walls)");
  // Walls across periodic sides contradict the dump.
  EXPECT_EQ(refusal(snapshot(0, atoms(), kPlain), {{"max_overlap", 0.5}, {"cylinder_radius", 2.0}}),
            "atoms.dump: timestep 0, line 5: params.cylinder_radius: expected no walls across "
            "the periodic x sides of the box, got a cylinder");
}

TEST_F(LammpsDump, AnAtomCentreBeyondTheDumpsOwnBoxIsRefused) {
  std::vector<Atom> list = atoms();
  list[0].x[0] = 4.5;  // id 3, beyond x = 4 of a box not periodic along x
  EXPECT_EQ(refusal(snapshot(0, list, kPlain, 0, "ff pp ff")),
            "atoms.dump: timestep 0, line 10: atom 3 at (4.5, 0.25, 0.5), radius 0.5: expected "
            "its centre inside the open side x_high (x = 4), got it 0.5 beyond (the dump's BOX "
            "BOUNDS, line 5)");
}

TEST_F(LammpsDump, AnAtomIdGivenTwiceIsRefusedWithBothLines) {
  std::vector<Atom> list = atoms();
  list[3].id = 3;  // line 13 repeats line 10's id
  EXPECT_EQ(refusal(snapshot(0, list, kPlain)),
            "atoms.dump: timestep 0, line 13: expected each atom id once, got id 3 again (first "
            "on line 10)");
}

// A dump appended to by a restarted run repeats timesteps: its frames went back in time,
// exit 0, and a contact dump joined by timestep gave the repeat the first one's contacts.
TEST_F(LammpsDump, TimestepsThatRepeatOrGoBackAreRefused) {
  const std::string first = snapshot(0, atoms(), kPlain), second = snapshot(100, atoms(), kPlain);
  const long lines = static_cast<long>(std::count(first.begin(), first.end(), '\n'));
  const std::string at = "atoms.dump: timestep 100, line " + std::to_string(2 * lines + 2) +
                         ": expected a timestep after 100 (the snapshot before, from line " +
                         std::to_string(lines + 1) + "), got 100";
  EXPECT_EQ(refusal(first + second + second),
            at + ": timesteps that repeat or go back (a run appended to its dump after a "
                 "restart, or a reset_timestep?)");
  EXPECT_EQ(refusal(first + second + first).substr(0, 60),
            ("atoms.dump: timestep 0, line " + std::to_string(2 * lines + 2) +
             ": expected a timestep after 100")
                .substr(0, 60));
}

TEST_F(LammpsDump, AtomLinesOtherThanNumberOfAtomsAreRefused) {
  const std::string text = snapshot(0, atoms(), kPlain);
  std::string more = text;
  more.replace(more.find("ATOMS\n4"), 7, "ATOMS\n3");
  EXPECT_EQ(refusal(more),
            "atoms.dump: timestep 0, line 13: expected 3 atom lines (NUMBER OF ATOMS, line 3), "
            "got more: \"2 1 2 -0.5 2 0.5 0.125 0 0\"");
  std::string fewer = text;
  fewer.replace(fewer.find("ATOMS\n4"), 7, "ATOMS\n5");
  EXPECT_EQ(refusal(fewer + snapshot(10, atoms(), kPlain)),
            "atoms.dump: timestep 0, line 14: expected 5 atom lines (NUMBER OF ATOMS, line 3), "
            "got 4 before \"ITEM: TIMESTEP\"");
}

TEST_F(LammpsDump, AValueThatIsNotANumberIsRefused) {
  std::string text = snapshot(0, atoms(), kPlain);
  std::string nan = text;
  nan.replace(nan.find("3.75 2.5 1"), 10, "3.75 nan 1");
  EXPECT_EQ(refusal(nan),
            "atoms.dump: timestep 0, line 11: expected a finite number in column 4 (y), got "
            "\"nan\"");
  std::string word = text;
  word.replace(word.find("3.75 2.5 1"), 10, "3.75 2.5 one");
  EXPECT_EQ(refusal(word),
            "atoms.dump: timestep 0, line 11: expected a finite number in column 5 (z), got "
            "\"one\"");
  std::string zero = text;
  zero.replace(zero.find(" 0.25 -1"), 8, " 0 -1");
  EXPECT_EQ(refusal(zero),
            "atoms.dump: timestep 0, line 11: expected a positive finite number in column 6 "
            "(radius), got \"0\"");
  std::string short_line = text;
  short_line.replace(short_line.find(" -1 0 0.5"), 9, " -1 0");
  EXPECT_EQ(refusal(short_line),
            "atoms.dump: timestep 0, line 11: expected 9 values (id type x y z radius vx vy vz), "
            "got 8: \"1 2 3.75 2.5 1 0.25 -1 0\"");
  std::string step = text;
  step.replace(step.find("TIMESTEP\n0"), 10, "TIMESTEP\nzero");
  EXPECT_EQ(refusal(step),
            "atoms.dump: line 2: expected the timestep, a whole number >= 0, got \"zero\"");
  // LAMMPS numbers atoms from 1: id 0 was read as an atom.
  std::string id_zero = text;
  id_zero.replace(id_zero.find("\n1 2 3.75"), 9, "\n0 2 3.75");
  EXPECT_EQ(refusal(id_zero),
            "atoms.dump: timestep 0, line 11: expected a whole number >= 1 in column 1 (id), got "
            "\"0\"");
}

TEST_F(LammpsDump, ColumnsThatChangeBetweenSnapshotsAreRefused) {
  EXPECT_EQ(refusal(snapshot(0, atoms(), kPlain) +
                    snapshot(10, atoms(), {"id", "type", "x", "y", "z", "radius"})),
            "atoms.dump: timestep 10, line 22: expected the columns of the first snapshot (\"id "
            "type x y z radius vx vy vz\"), got \"id type x y z radius\"");
}

TEST_F(LammpsDump, MissingOrPartialColumnsAreRefused) {
  EXPECT_EQ(refusal(snapshot(0, atoms(), {"id", "type", "x", "y", "z", "radius", "vx", "vz"})),
            "atoms.dump: timestep 0, line 9: expected vx, vy and vz together, got 2 of them in "
            "\"id type x y z radius vx vz\"");
  EXPECT_EQ(refusal(snapshot(0, atoms(), {"id", "type", "xs", "z", "radius"})),
            "atoms.dump: timestep 0, line 9: expected a position column along y (y, yu, ys or "
            "ysu), got \"id type xs z radius\"");
  EXPECT_EQ(refusal(snapshot(0, atoms(), {"id", "x", "y", "z", "radius", "vx", "vy"})),
            "atoms.dump: timestep 0, line 9: expected vx, vy and vz together, got 2 of them in "
            "\"id x y z radius vx vy\"");
}

// A 2D run's dump was refused in other words: a dump of x and y only as missing a z column,
// and LAMMPS's own 2D dump (every atom at z = 0, the box periodic along z and about an atom
// thick) only when the neighbour search found the box too thin, after validation.
TEST_F(LammpsDump, TwoDimensionalDumpsAreRefusedAsSuch) {
  const std::string reads_3d = "expected a 3D dump (granpipe's LAMMPS readers read 3D dumps), got ";
  EXPECT_EQ(refusal(snapshot(0, atoms(), {"id", "type", "x", "yu", "radius"})),
            "atoms.dump: timestep 0, line 9: " + reads_3d +
                "positions along x and y only (\"id type x yu radius\"): a 2D run's dump");
  std::vector<Atom> list = atoms();
  for (Atom& t : list) t.x[2] = 0.0;
  std::string text = snapshot(0, list, kPlain, 0, "pp pp pp");
  text.replace(text.find("\n0 10\n"), 6, "\n-0.5 0.5\n");
  EXPECT_EQ(refusal(text), "atoms.dump: timestep 0, line 5: " + reads_3d +
                               "every atom at z = 0 in a box periodic along z and 1 thick, no "
                               "more than an atom's diameter (1): a 2D run's dump");
  // A 2D run's box may be thicker than the disks (z bounds -5 to 5 for disks of 1): read as
  // spheres, exit 0. The same atoms off z = 0 are a 3D layer, read.
  text.replace(text.find("\n-0.5 0.5\n"), 10, "\n-5 5\n");
  EXPECT_EQ(refusal(text), "atoms.dump: timestep 0, line 5: " + reads_3d +
                               "every atom at z = 0 in a box periodic along z from -5 to 5: a 2D "
                               "run's dump (a 3D packing in the plane z = 0 cannot be told from "
                               "one: shift its atoms and box off z = 0 to have it read)");
  for (Atom& t : list) t.x[2] = 5.0;
  EXPECT_EQ(refusal(snapshot(0, list, kPlain, 0, "pp pp pp")), "accepted");
}

TEST_F(LammpsDump, FilesThatAreNotDumpsAreNamed) {
  EXPECT_EQ(refusal("LAMMPS data file via write_data\n\n2 atoms\n1 atom types\n"),
            "atoms.dump: line 1: expected a LAMMPS dump (starting \"ITEM: TIMESTEP\"), got a "
            "LAMMPS data file (\"2 atoms\" on line 3): use the lammps_data source");
  // HDF5's signature, then binary data.
  EXPECT_EQ(refusal(std::string("\x89HDF\r\n\x1a\n\0\0\0\0\0\x08\x08\0", 16)),
            "atoms.dump: line 1: expected a LAMMPS dump (starting \"ITEM: TIMESTEP\"), got an "
            "HDF5 file: use the h5md source for H5MD frames");
  EXPECT_EQ(refusal(""),
            "atoms.dump: expected a LAMMPS dump (starting \"ITEM: TIMESTEP\"), got an empty file");
  std::string local = snapshot(0, atoms(), kPlain);
  local.replace(local.find("NUMBER OF ATOMS"), 15, "NUMBER OF ENTRIES");
  EXPECT_EQ(refusal(local),
            "atoms.dump: timestep 0, line 3: expected \"ITEM: NUMBER OF ATOMS\", got \"ITEM: "
            "NUMBER OF ENTRIES\": a dump local (contacts, bonds), not a dump of atoms");
}
