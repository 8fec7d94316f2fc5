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

// granpipe's extension: per-frame datasets, row k belongs to frame k.
inline const std::string kExtension = "/granpipe";
inline const std::string kVersionAttr = "version";        // int32[2], {1, 0}
inline const std::string kCompleteAttr = "complete";      // int32, 0 until close()
inline const std::string kProvenanceAttr = "provenance";  // variable-length UTF-8 JSON
inline constexpr int kVersionMajor = 1, kVersionMinor = 0;

inline const std::string kRadius = kExtension + "/radius";
inline const std::string kAngularVelocity = kExtension + "/angular_velocity";
inline const std::string kTap = kExtension + "/tap";
inline const std::string kCycle = kExtension + "/cycle";
inline const std::string kSupports = kExtension + "/supports";

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
inline const std::string kContactI = kContacts + "/i";
inline const std::string kContactJ = kContacts + "/j";
inline const std::string kContactOverlap = kContacts + "/overlap";
inline const std::string kContactNormal = kContacts + "/normal_force";
inline const std::string kContactTangential = kContacts + "/tangential_force";
inline const std::string kContactPoint = kContacts + "/point";

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
