#pragma once
// frames.h5: frames as H5MD 1.1 plus granpipe's documented extensions
// (docs/file-format.md). The writer appends and flushes frame by frame in SWMR mode,
// so a run killed mid-way leaves every completed frame readable.
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "granpipe/frame.hpp"

namespace granpipe {

struct FrameFileInfo {
  std::string path;
  std::string group = "all";  // H5MD particles group read
  long frames = 0;
  long particles = 0;
  int dim = 0;
  bool complete = true;        // false: the writer never closed it (killed or crashed)
  bool granpipe_file = false;  // written by granpipe (has the extension groups)
  // What each frame holds beyond positions: particle columns (radius, velocity, a
  // plugin's own), per-frame observables, and the contact columns (when it has contacts).
  std::vector<Property> columns, observables, contact_columns;
  bool has_contacts = false;
  // Bytes of each stored position coordinate: 8 for doubles, 4 for the 32-bit floats other
  // tools write (6 to 7 digits: too coarse to find contacts from by distance).
  int position_bytes = 8;
  int radius_bytes = 8;  // the same for stored radii (contact distances are their sums)
  bool has(std::string_view column) const;
  std::string creator;     // /h5md/creator name and version
  std::string provenance;  // a granpipe file's run (JSON: pipeline, commit, seed, ...), else ""
};

class FrameWriter {
 public:
  // Creates `path` (which must not exist). `provenance_json` is stored as an attribute.
  FrameWriter(const std::filesystem::path& path, const std::string& provenance_json);
  ~FrameWriter();
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  // Appends one frame and flushes it to disk. Every frame must have the same N and dim
  // and carry the same optional arrays as the first.
  void append(const Frame& frame);
  // Marks the file complete and closes it. Without close() the file stays marked
  // incomplete (its frames still read back).
  void close();
  long frames() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class FrameReader {
 public:
  // Opens any H5MD file; `group` picks /particles/<group> (empty: the only group, or "all").
  // `default_radius` is used when the file has no radius (other tools' files).
  explicit FrameReader(const std::filesystem::path& path, const std::string& group = "",
                       double default_radius = 0.5);
  ~FrameReader();
  FrameReader(const FrameReader&) = delete;
  FrameReader& operator=(const FrameReader&) = delete;

  const FrameFileInfo& info() const;
  long frames() const { return info().frames; }
  Frame read(long index) const;

  // Another tool's walled box (H5MD stores no origin): per axis, whether the frames read to
  // place the walls allow them at [0, L] and at [-L/2, L/2] (both along a periodic axis).
  struct WallPlacements {
    std::array<bool, 3> at_zero{true, true, true}, centred{true, true, true};
  };
  WallPlacements wall_placements() const;
  // Puts the walls centred (true) or at [0, L] along each `settled` walled axis the frames
  // allow both on, the other parts of a run having decided: a run's parts placed alike.
  void place_walls_like(const std::array<bool, 3>& settled, const std::array<bool, 3>& centred);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace granpipe
