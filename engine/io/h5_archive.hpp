// Plain C++ data to and from an HDF5 group, with one list of members per type.
//
// A type takes part by a `fields(ar, x)` overload (found by argument-dependent lookup) that names
// each member once; the same list writes (Writer) and reads (Reader):
//   template <class Ar> void fields(Ar& ar, Contact& c) { ar("node", c.node); ar("t", c.t); }
// What a member becomes in the file:
//   number, bool, enum, string, Vec2, std::array of numbers   an attribute of the group
//   std::vector of those (strings excepted)                    a dataset: n, or n x N for arrays
//   std::vector of a flat struct (trivially copyable, fields)  a compound dataset, which h5py
//                                                              reads as a structured array
//   a struct with fields                                       a sub-group
//   std::vector of any other struct                            a sub-group with one per element
//   std::vector<std::vector<T>>                                a sub-group: "data" and "first"
//   std::optional<T>                                           as T, or nothing when empty
// The reader finds members by name: a missing one, or one of another shape, throws edem::Error
// naming its path in the file. Members of a flat struct are numbers, enums, bools, Vec2, arrays
// or flat structs.
#pragma once

#include <hdf5.h>

#include <array>
#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/vec2.hpp"

namespace edem::h5 {

// An HDF5 identifier, closed by the function that belongs to its kind.
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), close_(other.close_) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, -1);
      close_ = other.close_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  void reset() {
    if (id_ >= 0 && close_ != nullptr) close_(id_);
    id_ = -1;
  }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

// Silences HDF5's own printing of its error stack while alive (errors are ours to report).
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t old_func_ = nullptr;
  void* old_data_ = nullptr;
};

template <class T>
concept Scalar = std::is_arithmetic_v<T> || std::is_enum_v<T>;

template <class T>
struct small_array : std::false_type {};
template <Scalar T, size_t N>
struct small_array<std::array<T, N>> : std::true_type {
  using element = T;
  static constexpr size_t size = N;
};
template <Scalar T, size_t N>
struct small_array<T[N]> : std::true_type {
  using element = T;
  static constexpr size_t size = N;
};
template <size_t N>
struct small_array<std::array<Vec2, N>> : std::true_type {  // N points, 2N doubles in a row
  using element = double;
  static constexpr size_t size = 2 * N;
};
template <>
struct small_array<Vec2> : std::true_type {
  using element = double;
  static constexpr size_t size = 2;
};
template <class T>
concept SmallArray = small_array<T>::value;

// Counts nothing; only lets `Fielded` ask whether fields(ar, x) exists.
struct Probe {
  template <class T>
  void operator()(const char*, T&) {}
};

template <class T>
concept Fielded = requires(Probe& probe, T& x) { fields(probe, x); };

template <class T>
concept Flat = Fielded<T> && std::is_trivially_copyable_v<T> && !SmallArray<T>;

template <class T>
struct ragged : std::false_type {};
template <class T>
struct ragged<std::vector<std::vector<T>>> : std::true_type {
  using element = T;
};

// The in-memory HDF5 type of a scalar (enums as their underlying integer, bool as a byte).
template <Scalar T>
hid_t native_type() {
  if constexpr (std::is_enum_v<T>) {
    return native_type<std::underlying_type_t<T>>();
  } else if constexpr (std::is_same_v<T, bool>) {
    return H5T_NATIVE_UINT8;
  } else if constexpr (std::is_same_v<T, char>) {
    return H5T_NATIVE_CHAR;
  } else if constexpr (std::is_floating_point_v<T>) {
    static_assert(std::is_same_v<T, double>, "only double floating point");
    return H5T_NATIVE_DOUBLE;
  } else if constexpr (std::is_signed_v<T>) {
    static_assert(sizeof(T) == 1 || sizeof(T) == 4 || sizeof(T) == 8);
    if constexpr (sizeof(T) == 1) return H5T_NATIVE_INT8;
    if constexpr (sizeof(T) == 4) return H5T_NATIVE_INT32;
    return H5T_NATIVE_INT64;
  } else {
    static_assert(sizeof(T) == 1 || sizeof(T) == 4 || sizeof(T) == 8);
    if constexpr (sizeof(T) == 1) return H5T_NATIVE_UINT8;
    if constexpr (sizeof(T) == 4) return H5T_NATIVE_UINT32;
    return H5T_NATIVE_UINT64;
  }
}

template <Flat T>
Handle compound_type();

// The HDF5 type of a member of a flat struct.
template <class M>
Handle member_type() {
  if constexpr (Scalar<M>) {
    return Handle(H5Tcopy(native_type<M>()), H5Tclose);
  } else if constexpr (SmallArray<M>) {
    const hsize_t n = small_array<M>::size;
    return Handle(H5Tarray_create2(native_type<typename small_array<M>::element>(), 1, &n), H5Tclose);
  } else {
    static_assert(Flat<M>, "a member of a flat struct must be a number, an array or a flat struct");
    return compound_type<M>();
  }
}

// Adds each member of a flat struct to a compound type at its offset in a sample object.
struct CompoundBuilder {
  hid_t type;
  const char* base;
  template <class M>
  void operator()(const char* name, M& member) {
    const Handle mt = member_type<M>();
    const auto offset = static_cast<size_t>(reinterpret_cast<const char*>(&member) - base);
    if (H5Tinsert(type, name, offset, mt.get()) < 0) fail("HDF5 could not describe member '{}'", name);
  }
};

template <Flat T>
Handle compound_type() {
  T sample{};
  Handle type(H5Tcreate(H5T_COMPOUND, sizeof(T)), H5Tclose);
  CompoundBuilder builder{type.get(), reinterpret_cast<const char*>(&sample)};
  fields(builder, sample);
  return type;
}

// Low-level pieces shared by Writer and Reader (h5_archive.cpp). `path` names the object in
// messages.
void write_attribute(hid_t group, const char* name, hid_t type, const hsize_t* dims, int rank,
                     const void* data, const std::string& path);
void write_string_attribute(hid_t group, const char* name, const std::string& value, const std::string& path);
void write_dataset(hid_t group, const char* name, hid_t type, const hsize_t* dims, int rank,
                   const void* data, const std::string& path);
Handle create_group(hid_t parent, const char* name, const std::string& path);
Handle open_group(hid_t parent, const char* name, const std::string& path);
bool has_attribute(hid_t group, const char* name);
bool has_link(hid_t group, const char* name);
std::size_t link_count(hid_t group);  // objects in a group
// Reads an attribute of `count` elements (1 for a scalar) into `data`, as `type`.
void read_attribute(hid_t group, const char* name, hid_t type, size_t count, void* data, const std::string& path);
std::string read_string_attribute(hid_t group, const char* name, const std::string& path);
// The extents of a dataset, checked to have `rank` dimensions and, for rank 2, `columns` columns.
std::vector<hsize_t> dataset_extent(hid_t group, const char* name, int rank, hsize_t columns,
                                    const std::string& path);
// Reads a whole dataset as `type`; for a compound, first checks that the file has every member
// but those in `may_lack` (HDF5 leaves those as they are in `data`).
void read_dataset(hid_t group, const char* name, hid_t type, void* data, const std::string& path,
                  const std::vector<const char*>& may_lack = {});

// The members of a flat struct that files written before they existed lack, which reading
// leaves at their defaults: a `std::vector<const char*> later_members(const T*)` beside its
// fields() names them.
template <class T>
std::vector<const char*> members_older_files_lack() {
  if constexpr (requires(const T* p) { later_members(p); })
    return later_members(static_cast<const T*>(nullptr));
  else
    return {};
}

template <class T>
using vector_element = typename T::value_type;

template <class T>
struct is_vector : std::false_type {};
template <class T>
struct is_vector<std::vector<T>> : std::true_type {};

template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};

// Writes members into an HDF5 group.
class Writer {
 public:
  Writer(hid_t group, std::string path) : group_(group), path_(std::move(path)) {}

  template <class T>
  void operator()(const char* name, const T& x) {
    if constexpr (Scalar<T>) {
      write_attribute(group_, name, native_type<T>(), nullptr, 0, &x, at(name));
    } else if constexpr (std::is_same_v<T, std::string>) {
      write_string_attribute(group_, name, x, at(name));
    } else if constexpr (SmallArray<T>) {
      const hsize_t n = small_array<T>::size;
      write_attribute(group_, name, native_type<typename small_array<T>::element>(), &n, 1, &x, at(name));
    } else if constexpr (is_optional<T>::value) {
      if (x) (*this)(name, *x);
    } else if constexpr (ragged<T>::value) {
      write_ragged(name, x);
    } else if constexpr (is_vector<T>::value) {
      write_vector(name, x);
    } else {
      static_assert(Fielded<T>, "no fields() for this type");
      const Handle sub = create_group(group_, name, at(name));
      Writer inner(sub.get(), at(name));
      fields(inner, const_cast<T&>(x));  // the fields() lists take non-const refs; Writer only reads
    }
  }

  // A sub-group to write into by hand.
  Handle group(const char* name) const { return create_group(group_, name, at(name)); }
  hid_t id() const { return group_; }
  std::string at(const char* name) const { return path_ + "/" + name; }

 private:
  template <class E>
  void write_vector(const char* name, const std::vector<E>& v) {
    const hsize_t n = v.size();
    if constexpr (Scalar<E> && !std::is_same_v<E, bool>) {
      write_dataset(group_, name, native_type<E>(), &n, 1, v.data(), at(name));
    } else if constexpr (SmallArray<E>) {
      const hsize_t dims[2] = {n, small_array<E>::size};
      write_dataset(group_, name, native_type<typename small_array<E>::element>(), dims, 2, v.data(), at(name));
    } else if constexpr (Flat<E>) {
      const Handle type = compound_type<E>();
      write_dataset(group_, name, type.get(), &n, 1, v.data(), at(name));
    } else {
      static_assert(Fielded<E>, "no fields() for the element type");
      const Handle sub = create_group(group_, name, at(name));
      Writer inner(sub.get(), at(name));
      const auto count = static_cast<std::int64_t>(v.size());
      inner("count", count);
      for (size_t i = 0; i < v.size(); ++i) inner(std::to_string(i).c_str(), v[i]);
    }
  }

  template <class E>
  void write_ragged(const char* name, const std::vector<std::vector<E>>& v) {
    std::vector<std::int64_t> first{0};
    std::vector<E> data;
    for (const auto& row : v) {
      data.insert(data.end(), row.begin(), row.end());
      first.push_back(static_cast<std::int64_t>(data.size()));
    }
    const Handle sub = create_group(group_, name, at(name));
    Writer inner(sub.get(), at(name));
    inner("first", first);
    inner("data", data);
  }

  hid_t group_;
  std::string path_;
};

// Reads members from an HDF5 group written by Writer.
class Reader {
 public:
  Reader(hid_t group, std::string path) : group_(group), path_(std::move(path)) {}

  template <class T>
  void operator()(const char* name, T& x) {
    if constexpr (Scalar<T>) {
      if constexpr (std::is_same_v<T, bool>) {
        std::uint8_t byte = 0;
        read_attribute(group_, name, H5T_NATIVE_UINT8, 1, &byte, at(name));
        x = byte != 0;
      } else {
        read_attribute(group_, name, native_type<T>(), 1, &x, at(name));
      }
    } else if constexpr (std::is_same_v<T, std::string>) {
      x = read_string_attribute(group_, name, at(name));
    } else if constexpr (SmallArray<T>) {
      read_attribute(group_, name, native_type<typename small_array<T>::element>(), small_array<T>::size, &x,
                     at(name));
    } else if constexpr (is_optional<T>::value) {
      x.reset();
      if (has_attribute(group_, name) || has_link(group_, name)) {
        x.emplace();
        (*this)(name, *x);
      }
    } else if constexpr (ragged<T>::value) {
      read_ragged(name, x);
    } else if constexpr (is_vector<T>::value) {
      read_vector(name, x);
    } else {
      static_assert(Fielded<T>, "no fields() for this type");
      const Handle sub = open_group(group_, name, at(name));
      Reader inner(sub.get(), at(name));
      fields(inner, x);
    }
  }

  Handle group(const char* name) const { return open_group(group_, name, at(name)); }
  hid_t id() const { return group_; }
  std::string at(const char* name) const { return path_ + "/" + name; }

 private:
  template <class E>
  void read_vector(const char* name, std::vector<E>& v) {
    if constexpr (Scalar<E> || SmallArray<E> || Flat<E>) {
      const int rank = SmallArray<E> ? 2 : 1;
      hsize_t columns = 0;
      if constexpr (SmallArray<E>) columns = small_array<E>::size;
      const auto extent = dataset_extent(group_, name, rank, columns, at(name));
      v.assign(static_cast<size_t>(extent[0]), E{});
      if (v.empty()) return;
      if constexpr (Scalar<E>) {
        read_dataset(group_, name, native_type<E>(), v.data(), at(name));
      } else if constexpr (SmallArray<E>) {
        read_dataset(group_, name, native_type<typename small_array<E>::element>(), v.data(), at(name));
      } else {
        const Handle type = compound_type<E>();
        read_dataset(group_, name, type.get(), v.data(), at(name), members_older_files_lack<E>());
      }
    } else {
      static_assert(Fielded<E>, "no fields() for the element type");
      const Handle sub = open_group(group_, name, at(name));
      Reader inner(sub.get(), at(name));
      std::int64_t count = 0;
      inner("count", count);
      if (count < 0 || static_cast<std::size_t>(count) > link_count(sub.get()))
        fail("{}: a count of {} where it holds {}", at(name), count, link_count(sub.get()));
      v.assign(static_cast<size_t>(count), E{});
      for (size_t i = 0; i < v.size(); ++i) inner(std::to_string(i).c_str(), v[i]);
    }
  }

  template <class E>
  void read_ragged(const char* name, std::vector<std::vector<E>>& v) {
    const Handle sub = open_group(group_, name, at(name));
    Reader inner(sub.get(), at(name));
    std::vector<std::int64_t> first;
    std::vector<E> data;
    inner("first", first);
    inner("data", data);
    if (first.empty() || first.front() != 0 || first.back() != static_cast<std::int64_t>(data.size()))
      fail("{}: its offsets do not match its data", at(name));
    for (size_t i = 0; i + 1 < first.size(); ++i)
      if (first[i + 1] < first[i]) fail("{}: its offsets decrease", at(name));
    v.assign(first.size() - 1, {});
    for (size_t i = 0; i + 1 < first.size(); ++i) v[i].assign(data.begin() + first[i], data.begin() + first[i + 1]);
  }

  hid_t group_;
  std::string path_;
};

}  // namespace edem::h5
