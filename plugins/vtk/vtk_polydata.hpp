#pragma once
// One frame as a VTK XML PolyData file (.vtp; columns base64 "binary", cells ASCII): each particle
// a point and a vertex cell, with every particle column as point data (position excepted: it is the
// points); each contact between two particles a line from i to j, with every contact column but i
// and j as cell data. Contacts with a wall have no second point and are left out.
//
// VTK orders cells vertices first, then lines, and cell data has one value per cell: on
// the vertex cells contact columns hold NaN (real) or -1 (integer), "no contact".
#include <string>

#include "granpipe/frame.hpp"

namespace granpipe::vtk {

std::string polydata_xml(const Frame& frame);

}  // namespace granpipe::vtk
