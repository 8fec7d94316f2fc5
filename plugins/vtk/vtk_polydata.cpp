#include "vtk_polydata.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace granpipe::vtk {

namespace {

template <class T>
const char* vtk_type() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  return "Int32";
}

// Base64 of the bytes, as VTK's "binary" format wants: exact, and NaN survives (VTK's
// ASCII reader refuses "nan").
std::string base64(const std::vector<unsigned char>& bytes) {
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - k);
    std::uint32_t group = 0;
    for (std::size_t b = 0; b < 3; ++b) group = group << 8 | (b < n ? bytes[k + b] : 0u);
    for (std::size_t c = 0; c < 4; ++c) {
      text += c <= n ? digits[(group >> (18 - 6 * c)) & 63u] : '=';
    }
  }
  return text;
}

// The values preceded by their size in bytes (UInt64, the file's header_type), both in the
// machine's byte order, which the file states.
template <class T>
std::string encoded(const std::vector<T>& values) {
  const std::uint64_t size = values.size() * sizeof(T);
  std::vector<unsigned char> bytes(sizeof size + size);
  std::memcpy(bytes.data(), &size, sizeof size);
  if (size) std::memcpy(bytes.data() + sizeof size, values.data(), size);
  return base64(bytes);
}

// Rows of a column chosen by `rows`, preceded by `filler_rows` rows of "no value".
struct Selection {
  const std::vector<Eigen::Index>& rows;
  Eigen::Index filler_rows = 0;
};

// A column with one component per axis gets three in 2D (z = 0): viewers take vectors.
int written_components(const Column& c, int dim) {
  return c.property().components == kDimComponents && dim == 2 ? 3 : c.components();
}

std::string data_array(const Column& c, int dim, const Selection& selection) {
  const int components = written_components(c, dim);
  std::string text;
  std::visit(
      [&](const auto& a) {
        using T = typename std::decay_t<decltype(a)>::Scalar;
        const T none = std::is_same_v<T, double> ? std::numeric_limits<T>::quiet_NaN() : T(-1);
        std::vector<T> values(selection.filler_rows * components, none);
        for (Eigen::Index i : selection.rows) {
          for (int k = 0; k < components; ++k) values.push_back(k < a.cols() ? a(i, k) : T(0));
        }
        text = std::string("        <DataArray type=\"") + vtk_type<T>() + "\" Name=\"" + c.name() +
               "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"binary\">" +
               encoded(values);
      },
      c.storage());
  return text + "</DataArray>\n";
}

std::string cell_array(const char* name, const std::vector<std::int64_t>& values) {
  std::string text =
      std::string("        <DataArray type=\"Int64\" Name=\"") + name + "\" format=\"ascii\">";
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k) text += ' ';
    text += std::to_string(values[k]);
  }
  return text + "</DataArray>\n";
}

// Cells of `points_per_cell` points each, given as their points one after another.
std::string cells(const char* element, const std::vector<std::int64_t>& connectivity,
                  std::int64_t points_per_cell) {
  std::vector<std::int64_t> offsets;
  for (std::size_t end = points_per_cell; end <= connectivity.size(); end += points_per_cell) {
    offsets.push_back(static_cast<std::int64_t>(end));
  }
  return std::string("      <") + element + ">\n" + cell_array("connectivity", connectivity) +
         cell_array("offsets", offsets) + "      </" + element + ">\n";
}

std::vector<Eigen::Index> particle_contacts(const Frame& f) {
  std::vector<Eigen::Index> rows;
  if (!f.contacts) return rows;
  for (Eigen::Index c = 0; c < f.contacts->rows(); ++c) {
    if (partner::is_particle(f.contact_j()[c])) rows.push_back(c);
  }
  return rows;
}

std::string point_data(const Frame& f, const std::vector<Eigen::Index>& particles) {
  std::string text = "      <PointData>\n";
  for (std::size_t k = 1; k < f.particles.size(); ++k) {  // 0 is the position: the points
    text += data_array(f.particles.column(k), f.dim, {particles});
  }
  return text + "      </PointData>\n";
}

std::string cell_data(const Frame& f, const std::vector<Eigen::Index>& contacts) {
  std::string text = "      <CellData>\n";
  if (f.contacts) {
    for (std::size_t k = 2; k < f.contacts->size(); ++k) {  // 0 and 1, i and j: the lines
      text += data_array(f.contacts->column(k), f.dim, {contacts, f.size()});
    }
  }
  return text + "      </CellData>\n";
}

std::string points(const Frame& f, const std::vector<Eigen::Index>& particles) {
  return "      <Points>\n" + data_array(f.particles.column(0), f.dim, {particles}) +
         "      </Points>\n";
}

}  // namespace

std::string polydata_xml(const Frame& f) {
  std::vector<Eigen::Index> particles(static_cast<std::size_t>(f.size()));
  std::vector<std::int64_t> vertices(particles.size());
  for (Eigen::Index i = 0; i < f.size(); ++i) particles[i] = vertices[i] = i;
  const std::vector<Eigen::Index> contacts = particle_contacts(f);
  std::vector<std::int64_t> line_ends;
  for (Eigen::Index c : contacts) {
    line_ends.push_back(f.contact_i()[c]);
    line_ends.push_back(f.contact_j()[c]);
  }
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"" +
         std::string(std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian") +
         "\" header_type=\"UInt64\">\n"
         "  <PolyData>\n"
         "    <Piece NumberOfPoints=\"" +
         std::to_string(f.size()) + "\" NumberOfVerts=\"" + std::to_string(f.size()) +
         "\" NumberOfLines=\"" + std::to_string(contacts.size()) +
         "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n" + point_data(f, particles) +
         cell_data(f, contacts) + points(f, particles) + cells("Verts", vertices, 1) +
         cells("Lines", line_ends, 2) +
         "    </Piece>\n"
         "  </PolyData>\n"
         "</VTKFile>\n";
}

}  // namespace granpipe::vtk
