#include "io/h5_archive.hpp"

#include <algorithm>
#include <cstring>

namespace edem::h5 {

QuietErrors::QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &old_func_, &old_data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, old_func_, old_data_); }

namespace {

Handle dataspace(const hsize_t* dims, int rank) {
  return rank == 0 ? Handle(H5Screate(H5S_SCALAR), H5Sclose) : Handle(H5Screate_simple(rank, dims, nullptr), H5Sclose);
}

}  // namespace

void write_attribute(hid_t group, const char* name, hid_t type, const hsize_t* dims, int rank,
                     const void* data, const std::string& path) {
  const Handle space = dataspace(dims, rank);
  const Handle attribute(H5Acreate2(group, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (attribute.get() < 0 || H5Awrite(attribute.get(), type, data) < 0) fail("HDF5 could not write {}", path);
}

void write_string_attribute(hid_t group, const char* name, const std::string& value, const std::string& path) {
  // Fixed length, at least one byte (HDF5 has no empty string type); trailing NULs are padding.
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<size_t>(value.size(), 1));
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  std::string padded = value;
  padded.resize(std::max<size_t>(value.size(), 1), '\0');
  write_attribute(group, name, type.get(), nullptr, 0, padded.data(), path);
}

void write_dataset(hid_t group, const char* name, hid_t type, const hsize_t* dims, int rank,
                   const void* data, const std::string& path) {
  const Handle space = dataspace(dims, rank);
  // A flat struct is stored as its listed members only, packed: written in its own layout, the
  // bytes of a member left out of its fields() (and the padding) would go into the file too and
  // come back on reading, and a checkpoint test could not tell that the member is not stored.
  const Handle stored(H5Tcopy(type), H5Tclose);
  if (stored.get() < 0 || (H5Tget_class(type) == H5T_COMPOUND && H5Tpack(stored.get()) < 0))
    fail("HDF5 could not describe {}", path);
  const Handle set(
      H5Dcreate2(group, name, stored.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (set.get() < 0) fail("HDF5 could not create {}", path);
  if (dims[0] == 0) return;
  if (H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) fail("HDF5 could not write {}", path);
}

Handle create_group(hid_t parent, const char* name, const std::string& path) {
  Handle group(H5Gcreate2(parent, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (group.get() < 0) fail("HDF5 could not create group {}", path);
  return group;
}

bool has_attribute(hid_t group, const char* name) { return H5Aexists(group, name) > 0; }

bool has_link(hid_t group, const char* name) { return H5Lexists(group, name, H5P_DEFAULT) > 0; }

std::size_t link_count(hid_t group) {
  H5G_info_t info;
  return H5Gget_info(group, &info) < 0 ? 0 : static_cast<std::size_t>(info.nlinks);
}

Handle open_group(hid_t parent, const char* name, const std::string& path) {
  if (!has_link(parent, name)) fail("it has no {}", path);
  Handle group(H5Gopen2(parent, name, H5P_DEFAULT), H5Gclose);
  if (group.get() < 0) fail("{} is not a group", path);
  return group;
}

void read_attribute(hid_t group, const char* name, hid_t type, size_t count, void* data, const std::string& path) {
  if (!has_attribute(group, name)) fail("it has no {}", path);
  const Handle attribute(H5Aopen(group, name, H5P_DEFAULT), H5Aclose);
  const Handle space(H5Aget_space(attribute.get()), H5Sclose);
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  const Handle stored(H5Aget_type(attribute.get()), H5Tclose);
  if (points != static_cast<hssize_t>(count) || H5Tget_class(stored.get()) != H5Tget_class(type))
    fail("{} has the wrong type or size", path);
  if (H5Aread(attribute.get(), type, data) < 0) fail("HDF5 could not read {}", path);
}

std::string read_string_attribute(hid_t group, const char* name, const std::string& path) {
  if (!has_attribute(group, name)) fail("it has no {}", path);
  const Handle attribute(H5Aopen(group, name, H5P_DEFAULT), H5Aclose);
  const Handle stored(H5Aget_type(attribute.get()), H5Tclose);
  const Handle space(H5Aget_space(attribute.get()), H5Sclose);
  if (H5Tget_class(stored.get()) != H5T_STRING || H5Tis_variable_str(stored.get()) > 0 ||
      H5Sget_simple_extent_npoints(space.get()) != 1)
    fail("{} is not a string", path);
  const size_t size = H5Tget_size(stored.get());
  std::string value(size, '\0');
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), size);
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  if (H5Aread(attribute.get(), type.get(), value.data()) < 0) fail("HDF5 could not read {}", path);
  value.resize(std::strlen(value.c_str()));
  return value;
}

std::vector<hsize_t> dataset_extent(hid_t group, const char* name, int rank, hsize_t columns,
                                    const std::string& path) {
  if (!has_link(group, name)) fail("it has no {}", path);
  const Handle set(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  if (set.get() < 0) fail("{} is not a dataset", path);
  const Handle space(H5Dget_space(set.get()), H5Sclose);
  if (H5Sget_simple_extent_ndims(space.get()) != rank) fail("{} has {} dimensions, not {}", path,
                                                             H5Sget_simple_extent_ndims(space.get()), rank);
  std::vector<hsize_t> dims(static_cast<size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  if (rank == 2 && dims[1] != columns) fail("{} has {} columns, not {}", path, dims[1], columns);
  // No more elements than the file holds bytes for: an altered extent is refused before memory
  // is reserved for it.
  const Handle stored(H5Dget_type(set.get()), H5Tclose);
  const hsize_t element = H5Tget_size(stored.get()), bytes = H5Dget_storage_size(set.get());
  const hsize_t count = dims[0] * (rank == 2 ? dims[1] : 1);
  if (dims[0] > (hsize_t{1} << 40) || (count > 0 && (element == 0 || count > bytes / element)))
    fail("{} claims {} elements, more than the file holds", path, dims[0]);
  return dims;
}

void read_dataset(hid_t group, const char* name, hid_t type, void* data, const std::string& path,
                  const std::vector<const char*>& may_lack) {
  const Handle set(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  const Handle stored(H5Dget_type(set.get()), H5Tclose);
  if (H5Tget_class(stored.get()) != H5Tget_class(type)) fail("{} has the wrong type", path);
  if (H5Tget_class(type) == H5T_COMPOUND) {
    // HDF5 leaves members missing from the file untouched; a missing member is an error here
    // unless the struct names it as one that older files lack.
    const int members = H5Tget_nmembers(type);
    for (int i = 0; i < members; ++i) {
      char* member = H5Tget_member_name(type, static_cast<unsigned>(i));
      const bool found = H5Tget_member_index(stored.get(), member) >= 0;
      const std::string member_name = member;
      H5free_memory(member);
      const bool optional = std::any_of(may_lack.begin(), may_lack.end(),
                                        [&](const char* lacking) { return member_name == lacking; });
      if (!found && !optional) fail("{} has no member '{}'", path, member_name);
    }
  }
  if (H5Dread(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) fail("HDF5 could not read {}", path);
}

}  // namespace edem::h5
