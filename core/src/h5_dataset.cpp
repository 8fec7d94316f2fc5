#include "h5_dataset.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>

namespace granpipe::h5 {

std::string format_shape(const Shape& shape) {
  std::ostringstream s;
  s << '[';
  for (std::size_t k = 0; k < shape.size(); ++k) s << (k ? ", " : "") << shape[k];
  s << ']';
  return s.str();
}

bool exists(hid_t loc, const std::string& path) {
  // H5Lexists fails (rather than answering no) when a parent is missing, so walk down.
  std::size_t pos = path.front() == '/' ? 1 : 0;
  while (pos <= path.size()) {
    std::size_t end = path.find('/', pos);
    if (end == std::string::npos) end = path.size();
    if (end > pos && H5Lexists(loc, path.substr(0, end).c_str(), H5P_DEFAULT) <= 0) return false;
    pos = end + 1;
  }
  return true;
}

namespace {
// A link that leads nowhere (a soft link to a removed object, an external link to a
// missing file) is not an absent element: read as one, a file's radii became the default
// radius, exit 0.
H5I_type_t type_at(hid_t loc, const std::string& path) {
  if (!exists(loc, path)) return H5I_BADID;
  Object o(H5Oopen(loc, path.c_str(), H5P_DEFAULT));
  if (!o.valid()) {
    throw Error(path +
                ": expected a group or dataset, got a link that leads to none (a soft "
                "link to a removed object or an external link to a missing file)");
  }
  return H5Iget_type(o.id());
}
}  // namespace

bool is_group(hid_t loc, const std::string& path) { return type_at(loc, path) == H5I_GROUP; }
bool is_dataset(hid_t loc, const std::string& path) { return type_at(loc, path) == H5I_DATASET; }

std::vector<std::string> members(hid_t group, const std::string& path) {
  H5G_info_t info;
  check(H5Gget_info(group, &info), path + ": cannot list the group");
  std::vector<std::string> names;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t len =
        H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (len < 0) throw Error(path + ": cannot list the group");
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(len));
    names.push_back(std::move(name));
  }
  return names;
}

Object open_group(hid_t loc, const std::string& path) {
  return owned(H5Gopen2(loc, path.c_str(), H5P_DEFAULT), path + ": cannot open the group");
}

Object open_dataset(hid_t loc, const std::string& path) {
  return owned(H5Dopen2(loc, path.c_str(), H5P_DEFAULT), path + ": cannot open the dataset");
}

Object open_stored_dataset(hid_t loc, const std::string& path) {
  Object dataset = open_dataset(loc, path);
  check_stored(dataset.id(), path);
  return dataset;
}

namespace {
// What a reader may find beyond the stored data: a killed writer's extended but unwritten
// last frame, a small dataset never written (HDF5 allocates storage on the first write).
constexpr double kUnstoredAllowance = 16.0 * 1024 * 1024;
constexpr double kUnfilteredRatio = 2.0, kFilteredRatio = 1032.0;

std::string count_text(double n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", n);
  return buf;
}

// Bytes of the dataset in the file, at most the file's size (a crafted chunk index or
// contiguous extent may claim more).
double stored_bytes(hid_t dataset, const std::string& path) {
  Object file = owned(H5Iget_file_id(dataset), path + ": cannot find the file");
  hsize_t file_size = 0;
  check(H5Fget_filesize(file.id(), &file_size), path + ": cannot read the file size");
  return static_cast<double>(std::min<hsize_t>(H5Dget_storage_size(dataset), file_size));
}

bool filtered(hid_t dataset, const std::string& path) {
  Object dcpl = owned(H5Dget_create_plist(dataset), path + ": cannot read the storage layout");
  return H5Pget_nfilters(dcpl.id()) > 0;
}
}  // namespace

void check_stored(hid_t dataset, const std::string& path) {
  const Shape shape = shape_of(dataset, path);
  Object type = owned(H5Dget_type(dataset), path + ": cannot read the data type");
  double bytes = static_cast<double>(H5Tget_size(type.id()));
  for (hsize_t n : shape) bytes *= static_cast<double>(n);
  const double rows = shape.empty() ? 1.0 : static_cast<double>(shape[0]);
  const double stored = stored_bytes(dataset, path);
  const double ratio = filtered(dataset, path) ? kFilteredRatio : kUnfilteredRatio;
  const double allowed = kUnstoredAllowance + ratio * stored;
  const std::string found = " for the " + count_text(stored) +
                            " bytes stored in the file, got shape " + format_shape(shape);
  if (bytes > allowed) {
    throw Error(path + ": expected at most " + count_text(allowed) + " bytes of data" + found +
                " (" + count_text(bytes) + " bytes; damaged or crafted file)");
  }
  // Rows of an empty item take no bytes, but a reader keeps a step and a time for each.
  if (rows > allowed) {
    throw Error(path + ": expected at most " + count_text(allowed) + " rows" + found +
                " (damaged or crafted file)");
  }
}

Object create_group(hid_t loc, const std::string& path) {
  Object lcpl = owned(H5Pcreate(H5P_LINK_CREATE), path + ": cannot create the group");
  check(H5Pset_create_intermediate_group(lcpl.id(), 1), path + ": cannot create the group");
  return owned(H5Gcreate2(loc, path.c_str(), lcpl.id(), H5P_DEFAULT, H5P_DEFAULT),
               path + ": cannot create the group");
}

Shape shape_of(hid_t dataset, const std::string& path) {
  Object space = owned(H5Dget_space(dataset), path + ": cannot read the shape");
  const int rank = H5Sget_simple_extent_ndims(space.id());
  if (rank < 0) throw Error(path + ": cannot read the shape");
  Shape dims(static_cast<std::size_t>(rank));
  if (rank > 0)
    check(H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr),
          path + ": cannot read the shape");
  return dims;
}

Object create_series(hid_t loc, const std::string& path, hid_t file_type, const Shape& item,
                     hsize_t chunk_rows, hid_t fill_type, const void* fill) {
  Shape dims{0}, maxdims{H5S_UNLIMITED}, chunk{chunk_rows};
  for (hsize_t n : item) {
    dims.push_back(n);
    // A chunk axis cannot be empty nor exceed a fixed maximum, so an empty axis (a
    // frame without particles) may grow to one.
    maxdims.push_back(std::max<hsize_t>(n, 1));
    chunk.push_back(std::max<hsize_t>(n, 1));
  }
  const int rank = static_cast<int>(dims.size());
  Object space = owned(H5Screate_simple(rank, dims.data(), maxdims.data()),
                       path + ": cannot make the dataspace");
  Object dcpl = owned(H5Pcreate(H5P_DATASET_CREATE), path + ": cannot make the property list");
  check(H5Pset_chunk(dcpl.id(), rank, chunk.data()), path + ": cannot set the chunk shape");
  if (fill) check(H5Pset_fill_value(dcpl.id(), fill_type, fill), path + ": cannot set the fill");
  Object dapl = owned(H5Pcreate(H5P_DATASET_ACCESS), path + ": cannot make the property list");
  check(H5Pset_chunk_cache(dapl.id(), 0, 0, 1.0), path + ": cannot disable the chunk cache");
  return owned(
      H5Dcreate2(loc, path.c_str(), file_type, space.id(), H5P_DEFAULT, dcpl.id(), dapl.id()),
      path + ": cannot create the dataset");
}

namespace {
// The hyperslab of `count` rows from `first`, and a memory space of the same shape.
struct Slab {
  Object file_space, mem_space;
};

Slab select_rows(hid_t dataset, const std::string& path, hsize_t first, hsize_t count) {
  Slab s;
  s.file_space = owned(H5Dget_space(dataset), path + ": cannot read the shape");
  const int rank = H5Sget_simple_extent_ndims(s.file_space.id());
  if (rank < 1) throw Error(path + ": expected an array with a frame axis");
  Shape dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(s.file_space.id(), dims.data(), nullptr);
  if (first + count > dims[0]) {
    throw Error(path + ": rows " + std::to_string(first) + ".." + std::to_string(first + count) +
                " requested, the dataset has " + std::to_string(dims[0]));
  }
  Shape start(dims.size(), 0), extent = dims;
  start[0] = first;
  extent[0] = count;
  check(H5Sselect_hyperslab(s.file_space.id(), H5S_SELECT_SET, start.data(), nullptr, extent.data(),
                            nullptr),
        path + ": cannot select rows");
  s.mem_space =
      owned(H5Screate_simple(rank, extent.data(), nullptr), path + ": cannot make the dataspace");
  return s;
}
}  // namespace

void append_rows(hid_t dataset, const std::string& path, hid_t mem_type, const void* data,
                 hsize_t rows) {
  if (rows == 0) return;
  Shape dims = shape_of(dataset, path);
  const hsize_t first = dims[0];
  dims[0] += rows;
  check(H5Dset_extent(dataset, dims.data()), path + ": cannot extend the dataset");
  Slab s = select_rows(dataset, path, first, rows);
  check(H5Dwrite(dataset, mem_type, s.mem_space.id(), s.file_space.id(), H5P_DEFAULT, data),
        path + ": cannot write");
}

void read_rows(hid_t dataset, const std::string& path, hid_t mem_type, hsize_t first, hsize_t count,
               void* out) {
  if (count == 0) return;
  Slab s = select_rows(dataset, path, first, count);
  check(H5Dread(dataset, mem_type, s.mem_space.id(), s.file_space.id(), H5P_DEFAULT, out),
        path + ": cannot read (unexpected data type or damaged data)");
}

void read_all(hid_t dataset, const std::string& path, hid_t mem_type, void* out) {
  check(H5Dread(dataset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out),
        path + ": cannot read (unexpected data type or damaged data)");
}

namespace {
template <class Signed, class Unsigned>
std::int64_t widen_as(const unsigned char* p, bool is_signed) {
  Signed s;
  Unsigned u;
  std::memcpy(&s, p, sizeof s);
  std::memcpy(&u, p, sizeof u);
  return is_signed ? static_cast<std::int64_t>(s) : static_cast<std::int64_t>(u);
}

// HDF5 converts an unsigned 64-bit integer past the largest signed one to that one,
// without a word.
std::int64_t checked_signed(std::uint64_t u, const std::string& path) {
  if (u <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    return static_cast<std::int64_t>(u);
  throw Error(path + ": expected integers up to " +
              std::to_string(std::numeric_limits<std::int64_t>::max()) + ", got " +
              std::to_string(u));
}

std::vector<std::int64_t> checked_signed(const std::vector<std::uint64_t>& raw,
                                         const std::string& path) {
  std::vector<std::int64_t> out(raw.size());
  for (std::size_t k = 0; k < raw.size(); ++k) out[k] = checked_signed(raw[k], path);
  return out;
}

// An integer type whose values HDF5 would clamp on the way to int64.
bool wide_unsigned(hid_t type) {
  return H5Tget_sign(type) == H5T_SGN_NONE && H5Tget_size(type) >= 8;
}

// An integer of `size` bytes in native byte order, widened to 64 bits.
std::int64_t widen(const unsigned char* p, std::size_t size, bool is_signed,
                   const std::string& path) {
  switch (size) {
    case 1:
      return widen_as<std::int8_t, std::uint8_t>(p, is_signed);
    case 2:
      return widen_as<std::int16_t, std::uint16_t>(p, is_signed);
    case 4:
      return widen_as<std::int32_t, std::uint32_t>(p, is_signed);
    case 8: {
      if (is_signed) return widen_as<std::int64_t, std::int64_t>(p, true);
      std::uint64_t u;
      std::memcpy(&u, p, sizeof u);
      return checked_signed(u, path);
    }
    default:
      throw Error(path + ": unsupported enumeration width " + std::to_string(size));
  }
}
}  // namespace

namespace {
// What a dataset holds, for a message (species written as strings read "another data type").
std::string type_class_name(H5T_class_t cls) {
  switch (cls) {
    case H5T_FLOAT:
      return "real numbers";
    case H5T_STRING:
      return "strings";
    case H5T_COMPOUND:
      return "compound records";
    case H5T_ARRAY:
      return "arrays";
    case H5T_VLEN:
      return "variable-length sequences";
    case H5T_BITFIELD:
      return "bit fields";
    case H5T_OPAQUE:
      return "opaque bytes";
    case H5T_REFERENCE:
      return "references";
    default:
      return "another data type";
  }
}
}  // namespace

std::vector<std::int64_t> read_integer_rows(hid_t dataset, const std::string& path, hsize_t first,
                                            hsize_t count) {
  Shape dims = shape_of(dataset, path);
  hsize_t per_row = 1;
  for (std::size_t k = 1; k < dims.size(); ++k) per_row *= dims[k];
  std::vector<std::int64_t> values(count * per_row);
  Object type = owned(H5Dget_type(dataset), path + ": cannot read the data type");
  const H5T_class_t cls = H5Tget_class(type.id());
  if (cls == H5T_INTEGER && wide_unsigned(type.id())) {
    std::vector<std::uint64_t> raw(values.size());
    read_rows(dataset, path, H5T_NATIVE_UINT64, first, count, raw.data());
    return checked_signed(raw, path);
  }
  if (cls == H5T_INTEGER) {
    read_rows(dataset, path, H5T_NATIVE_INT64, first, count, values.data());
    return values;
  }
  if (cls != H5T_ENUM) {
    throw Error(path + ": expected integers (or an enumeration), got " + type_class_name(cls));
  }
  // HDF5 converts an enumeration only to another enumeration: read the native form of
  // the enumeration and widen its integer base type by hand.
  Object native =
      owned(H5Tget_native_type(type.id(), H5T_DIR_ASCEND), path + ": cannot read the data type");
  Object base = owned(H5Tget_super(native.id()), path + ": cannot read the data type");
  const std::size_t size = H5Tget_size(base.id());
  const bool is_signed = H5Tget_sign(base.id()) == H5T_SGN_2;
  std::vector<unsigned char> raw(values.size() * size);
  read_rows(dataset, path, native.id(), first, count, raw.data());
  for (std::size_t k = 0; k < values.size(); ++k) {
    values[k] = widen(raw.data() + k * size, size, is_signed, path);
  }
  return values;
}

namespace {
void write_raw_attribute(hid_t object, const std::string& name, hid_t type, hid_t space,
                         const void* data) {
  if (H5Aexists(object, name.c_str()) > 0) {
    check(H5Adelete(object, name.c_str()), name + ": cannot replace the attribute");
  }
  Object attr = owned(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                      name + ": cannot create the attribute");
  check(H5Awrite(attr.id(), type, data), name + ": cannot write the attribute");
}

Object fixed_string_type(std::size_t length) {
  Object type = owned(H5Tcopy(H5T_C_S1), "cannot make a string type");
  check(H5Tset_size(type.id(), std::max<std::size_t>(length, 1)), "cannot size a string type");
  check(H5Tset_strpad(type.id(), H5T_STR_NULLPAD), "cannot make a string type");
  return type;
}
}  // namespace

void write_attribute(hid_t object, const std::string& name, const std::string& value) {
  Object type = fixed_string_type(value.size());
  Object space = owned(H5Screate(H5S_SCALAR), name + ": cannot make the dataspace");
  std::string padded = value;
  padded.resize(std::max<std::size_t>(value.size(), 1), '\0');
  write_raw_attribute(object, name, type.id(), space.id(), padded.data());
}

void write_attribute(hid_t object, const std::string& name,
                     const std::vector<std::string>& values) {
  std::size_t width = 1;
  for (const auto& v : values) width = std::max(width, v.size());
  Object type = fixed_string_type(width);
  const hsize_t n = values.size();
  Object space = owned(H5Screate_simple(1, &n, nullptr), name + ": cannot make the dataspace");
  std::string buffer(width * values.size(), '\0');
  for (std::size_t k = 0; k < values.size(); ++k) {
    std::copy(values[k].begin(), values[k].end(), buffer.begin() + static_cast<long>(k * width));
  }
  write_raw_attribute(object, name, type.id(), space.id(), buffer.data());
}

void write_attribute(hid_t object, const std::string& name, const std::vector<int>& values) {
  const hsize_t n = values.size();
  Object space = owned(H5Screate_simple(1, &n, nullptr), name + ": cannot make the dataspace");
  Object type = owned(H5Tcopy(H5T_STD_I32LE), name + ": cannot make the type");
  write_raw_attribute(object, name, type.id(), space.id(), values.data());
}

void write_attribute(hid_t object, const std::string& name, const std::vector<double>& values) {
  const hsize_t n = values.size();
  Object space = owned(H5Screate_simple(1, &n, nullptr), name + ": cannot make the dataspace");
  write_raw_attribute(object, name, H5T_IEEE_F64LE, space.id(), values.data());
}

void write_attribute(hid_t object, const std::string& name, int value) {
  Object space = owned(H5Screate(H5S_SCALAR), name + ": cannot make the dataspace");
  write_raw_attribute(object, name, H5T_STD_I32LE, space.id(), &value);
}

void write_attribute(hid_t object, const std::string& name, double value) {
  Object space = owned(H5Screate(H5S_SCALAR), name + ": cannot make the dataspace");
  write_raw_attribute(object, name, H5T_IEEE_F64LE, space.id(), &value);
}

void write_attribute(hid_t object, const std::string& name, std::uint64_t value) {
  Object space = owned(H5Screate(H5S_SCALAR), name + ": cannot make the dataspace");
  write_raw_attribute(object, name, H5T_STD_U64LE, space.id(), &value);
}

void write_text_attribute(hid_t object, const std::string& name, const std::string& value) {
  Object type = owned(H5Tcopy(H5T_C_S1), name + ": cannot make a string type");
  check(H5Tset_size(type.id(), H5T_VARIABLE), name + ": cannot make a string type");
  check(H5Tset_cset(type.id(), H5T_CSET_UTF8), name + ": cannot make a string type");
  Object space = owned(H5Screate(H5S_SCALAR), name + ": cannot make the dataspace");
  const char* text = value.c_str();
  write_raw_attribute(object, name, type.id(), space.id(), &text);
}

bool has_attribute(hid_t object, const std::string& name) {
  return H5Aexists(object, name.c_str()) > 0;
}

namespace {
struct OpenAttribute {
  Object attr, type, space;
  hsize_t count = 0;
};

OpenAttribute open_attribute(hid_t object, const std::string& where) {
  OpenAttribute a;
  const std::string name = where.substr(where.rfind('@') + 1);
  a.attr = owned(H5Aopen(object, name.c_str(), H5P_DEFAULT), where + ": missing attribute");
  a.type = owned(H5Aget_type(a.attr.id()), where + ": cannot read the attribute type");
  a.space = owned(H5Aget_space(a.attr.id()), where + ": cannot read the attribute shape");
  const hssize_t n = H5Sget_simple_extent_npoints(a.space.id());
  if (n < 0) throw Error(where + ": cannot read the attribute shape");
  a.count = static_cast<hsize_t>(n);
  return a;
}
}  // namespace

std::vector<std::string> read_string_attribute(hid_t object, const std::string& path,
                                               const std::string& name) {
  const std::string where = path + "@" + name;
  OpenAttribute a = open_attribute(object, where);
  if (H5Tget_class(a.type.id()) != H5T_STRING) throw Error(where + ": expected text");
  std::vector<std::string> out;
  if (H5Tis_variable_str(a.type.id()) > 0) {
    Object mem = owned(H5Tcopy(H5T_C_S1), where + ": cannot make a string type");
    H5Tset_size(mem.id(), H5T_VARIABLE);
    H5Tset_cset(mem.id(), H5Tget_cset(a.type.id()));
    std::vector<char*> texts(a.count, nullptr);
    check(H5Aread(a.attr.id(), mem.id(), texts.data()), where + ": cannot read the attribute");
    for (char* t : texts) {
      out.emplace_back(t ? t : "");
      H5free_memory(t);
    }
    return out;
  }
  const std::size_t width = H5Tget_size(a.type.id());
  std::string buffer(width * a.count, '\0');
  check(H5Aread(a.attr.id(), a.type.id(), buffer.data()), where + ": cannot read the attribute");
  for (hsize_t k = 0; k < a.count; ++k) {
    std::string s = buffer.substr(k * width, width);
    s = s.substr(0, s.find('\0'));
    // Fortran-style files pad with spaces.
    s.erase(s.find_last_not_of(' ') + 1);
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::int64_t> read_integer_attribute(hid_t object, const std::string& path,
                                                 const std::string& name) {
  const std::string where = path + "@" + name;
  OpenAttribute a = open_attribute(object, where);
  if (H5Tget_class(a.type.id()) != H5T_INTEGER) throw Error(where + ": expected integers");
  std::vector<std::int64_t> out(a.count);
  if (wide_unsigned(a.type.id())) {
    std::vector<std::uint64_t> raw(a.count);
    check(H5Aread(a.attr.id(), H5T_NATIVE_UINT64, raw.data()),
          where + ": cannot read the attribute");
    return checked_signed(raw, where);
  }
  check(H5Aread(a.attr.id(), H5T_NATIVE_INT64, out.data()), where + ": cannot read the attribute");
  return out;
}

std::vector<double> read_real_attribute(hid_t object, const std::string& path,
                                        const std::string& name) {
  const std::string where = path + "@" + name;
  OpenAttribute a = open_attribute(object, where);
  const H5T_class_t cls = H5Tget_class(a.type.id());
  if (cls != H5T_INTEGER && cls != H5T_FLOAT) throw Error(where + ": expected numbers");
  std::vector<double> out(a.count);
  check(H5Aread(a.attr.id(), H5T_NATIVE_DOUBLE, out.data()), where + ": cannot read the attribute");
  return out;
}

}  // namespace granpipe::h5
