#pragma once
// Columns of a frame (property_table.hpp) to and from HDF5 rows, for the frames.h5
// writer and reader. A particle column is one row of shape [N] or [N][components] per
// frame; a contact column is one row per contact.
#include <hdf5.h>

#include <string>

#include "granpipe/property_table.hpp"
#include "h5_dataset.hpp"

namespace granpipe::h5 {

// The little-endian file type of a value type.
hid_t file_type(ValueType t);
// The value type of a stored dataset (float: real; 64-bit integer: integer; narrower
// integer or enumeration: small); throws h5::Error for anything else.
ValueType value_type_of(hid_t dataset, const std::string& path);

// The per-row shape of a column in a file: {} for one value, {c} for c components;
// per-particle columns put [N] in front.
Shape item_shape(const Column& c);

// Appends `rows` rows holding every value of `c` (C order).
void append_column(hid_t dataset, const std::string& path, const Column& c, hsize_t rows);
// Reads `count` rows starting at `first` into `c`, which is sized to hold them.
void read_column(hid_t dataset, const std::string& path, hsize_t first, hsize_t count, Column& c);

// Attributes that let a column read back as the property it was written from.
void write_property_attributes(hid_t dataset, const Property& p);
// The property of a stored column: from the standard table when `name` is standard,
// else from the attributes (or, for other tools' files, from the dataset's type and
// shape). `item` is the per-row shape after the particle axis.
Property read_property(hid_t dataset, const std::string& path, const std::string& name, Scope scope,
                       const Shape& item, int dim);

}  // namespace granpipe::h5
