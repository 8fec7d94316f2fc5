#pragma once
// Small HDF5 building blocks shared by the frame writer and reader: paths, extendable
// series of rows, reading rows back, and string/integer attributes. Every failure throws
// h5::Error naming the object path.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "h5_object.hpp"

namespace granpipe::h5 {

using Shape = std::vector<hsize_t>;
std::string format_shape(const Shape& shape);  // "[3, 100, 3]"

// True when every component of `path` exists (no error for a missing parent).
bool exists(hid_t loc, const std::string& path);
bool is_group(hid_t loc, const std::string& path);
bool is_dataset(hid_t loc, const std::string& path);
// Names of the direct members of a group, in name order.
std::vector<std::string> members(hid_t group, const std::string& path);

Object open_group(hid_t loc, const std::string& path);
Object open_dataset(hid_t loc, const std::string& path);
// A dataset to read from a file that may be damaged or crafted: refused when its shape
// declares far more data than the file stores (see check_stored).
Object open_stored_dataset(hid_t loc, const std::string& path);
// HDF5 reads what a file never stored as the fill value, so an 8 KB file may declare
// gigabytes, which a reader would allocate before reading. Refuses a dataset whose
// declared bytes (or rows) exceed 16 MB beyond twice what it stores, or 1032 times (the
// most deflate compresses) when it is filtered, counting no more than the file's size.
void check_stored(hid_t dataset, const std::string& path);
Object create_group(hid_t loc, const std::string& path);  // with any missing parents
Shape shape_of(hid_t dataset, const std::string& path);

// An extendable series: zero rows of shape `item`, chunked by `chunk_rows` rows along an
// unlimited first axis. Writes bypass the chunk cache, so every row reaches the file in
// the order it was written: a process killed between two writes leaves the first on disk.
Object create_series(hid_t loc, const std::string& path, hid_t file_type, const Shape& item,
                     hsize_t chunk_rows, hid_t fill_type = H5I_INVALID_HID,
                     const void* fill = nullptr);
// Extends the series by `rows` rows and writes them from `data` (C order).
void append_rows(hid_t dataset, const std::string& path, hid_t mem_type, const void* data,
                 hsize_t rows);
// Reads `count` rows starting at `first` (every further axis whole) into `out`.
void read_rows(hid_t dataset, const std::string& path, hid_t mem_type, hsize_t first, hsize_t count,
               void* out);
// Reads a whole dataset (any rank, scalar included) into `out`.
void read_all(hid_t dataset, const std::string& path, hid_t mem_type, void* out);
// As read_rows, for integer or enumeration datasets of any width, as 64-bit integers.
std::vector<std::int64_t> read_integer_rows(hid_t dataset, const std::string& path, hsize_t first,
                                            hsize_t count);

// Attributes. H5MD asks for fixed-length strings; `write_text_attribute` stores a
// variable-length UTF-8 string, for text of any length (provenance JSON).
void write_attribute(hid_t object, const std::string& name, const std::string& value);
void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values);
void write_attribute(hid_t object, const std::string& name, const std::vector<int>& values);
void write_attribute(hid_t object, const std::string& name, const std::vector<double>& values);
void write_attribute(hid_t object, const std::string& name, int value);
void write_attribute(hid_t object, const std::string& name, double value);
void write_attribute(hid_t object, const std::string& name, std::uint64_t value);
void write_text_attribute(hid_t object, const std::string& name, const std::string& value);
bool has_attribute(hid_t object, const std::string& name);
// Any string attribute, fixed or variable length, scalar (one item) or 1-D.
std::vector<std::string> read_string_attribute(hid_t object, const std::string& path,
                                               const std::string& name);
// Any integer attribute, scalar (one item) or 1-D.
std::vector<std::int64_t> read_integer_attribute(hid_t object, const std::string& path,
                                                 const std::string& name);
// Any numeric attribute, scalar (one item) or 1-D, as doubles.
std::vector<double> read_real_attribute(hid_t object, const std::string& path,
                                        const std::string& name);

}  // namespace granpipe::h5
