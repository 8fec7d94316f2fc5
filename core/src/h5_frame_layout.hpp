#pragma once
// Names and types of frames.h5, shared by the writer and the reader. The layout itself
// is documented in docs/file-format.md; keep the two in step.
#include <hdf5.h>

#include <string>

#include "granpipe/container.hpp"
#include "h5_object.hpp"

namespace granpipe::frame_layout {

// H5MD part. granpipe writes one particles group, "all".
inline const std::string kParticles = "/particles";
inline const std::string kGroup = "all";
inline std::string particles(const std::string& group) { return kParticles + "/" + group; }

// granpipe's extension: the container and the contacts, row k of a per-frame dataset
// belongs to frame k. Every particle column is an H5MD element of the particles group.
inline const std::string kExtension = "/granpipe";
inline const std::string kVersionAttr = "version";        // int32[2], {2, 0}
inline const std::string kCompleteAttr = "complete";      // int32, 0 until close()
inline const std::string kProvenanceAttr = "provenance";  // variable-length UTF-8 JSON
// The order of the columns of each table, as the writer's frames held them (HDF5 lists
// group members by name).
inline const std::string kParticleColumnsAttr = "particle_columns";
inline const std::string kObservablesAttr = "observables";
inline const std::string kContactColumnsAttr = "contact_columns";
inline constexpr int kVersionMajor = 2, kVersionMinor = 0;

// H5MD observables: one element per per-frame observable (tap, cycle, amplitude, ...).
inline const std::string kObservables = "/observables";

inline const std::string kContainer = kExtension + "/container";
inline const std::string kShape = kContainer + "/shape";
inline const std::string kLo = kContainer + "/lo";
inline const std::string kHi = kContainer + "/hi";
inline const std::string kBoundary = kContainer + "/boundary";
inline const std::string kCylinderRadius = kContainer + "/cylinder_radius";
inline const std::string kCylinderCenter = kContainer + "/cylinder_center";
inline const std::string kWallOffset = kContainer + "/wall_offset";
inline const std::string kWallVelocity = kContainer + "/wall_velocity";

inline const std::string kContacts = kExtension + "/contacts";
inline const std::string kContactOffset = kContacts + "/offset";
inline const std::string kContactCount = kContacts + "/count";
// Then one dataset per contact column (i, j, overlap, normal_force, ...), rows of all
// frames concatenated: frame k holds rows offset[k] .. offset[k] + count[k].

// The step of a row not yet written: the writer commits a frame by writing its step
// last, so a reader drops trailing rows that still hold this fill value.
inline constexpr long long kUnwrittenStep = -0x7fffffffffffffffLL - 1;

// Enumerations stored as HDF5 enum types over uint8, so that h5py and h5dump show names.
inline h5::Object boundary_type() {
  h5::Object t = h5::owned(H5Tenum_create(H5T_STD_U8LE), "cannot make the boundary type");
  for (Boundary b : {Boundary::Wall, Boundary::Periodic, Boundary::Open}) {
    const auto v = static_cast<unsigned char>(b);
    h5::check(H5Tenum_insert(t.id(), to_string(b), &v), "cannot make the boundary type");
  }
  return t;
}

inline h5::Object shape_type() {
  h5::Object t = h5::owned(H5Tenum_create(H5T_STD_U8LE), "cannot make the shape type");
  for (ContainerShape s : {ContainerShape::Box, ContainerShape::Cylinder}) {
    const auto v = static_cast<unsigned char>(s);
    h5::check(H5Tenum_insert(t.id(), to_string(s), &v), "cannot make the shape type");
  }
  return t;
}

}  // namespace granpipe::frame_layout
