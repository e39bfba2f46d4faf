#include "hdf5_io.hpp"

#include <algorithm>

namespace peristep::hdf5 {

Handle::Handle(hid_t id, Closer closer, const std::string& what) : id_(id), closer_(closer) {
  if (id_ < 0) throw Error("HDF5: cannot " + what);
}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_, closer_ = other.closer_;
    other.id_ = -1;
  }
  return *this;
}

void Handle::reset() {
  if (id_ >= 0) closer_(id_);
  id_ = -1;
}

void Handle::close(const std::string& what) {
  const hid_t id = id_;
  id_ = -1;
  if (id >= 0) check(closer_(id), what);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error("HDF5: cannot " + what);
}

Handle createFile(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  return {H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "create " + path};
}

Handle openFile(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  return {H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path};
}

Handle createGroup(hid_t parent, const std::string& path) {
  Handle props(H5Pcreate(H5P_LINK_CREATE), H5Pclose, "create link properties");
  check(H5Pset_create_intermediate_group(props, 1), "allow intermediate groups");
  return {H5Gcreate2(parent, path.c_str(), props, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create group " + path};
}

Handle openGroup(hid_t parent, const std::string& path) {
  return {H5Gopen2(parent, path.c_str(), H5P_DEFAULT), H5Gclose, "open group " + path};
}

void writeString(hid_t object, const std::string& name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(type, std::max<std::size_t>(1, value.size())), "size a string");
  check(H5Tset_strpad(type, H5T_STR_NULLTERM), "pad a string");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
  Handle attr(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
              "create attribute " + name);
  const std::string padded = value.empty() ? std::string(1, '\0') : value;
  check(H5Awrite(attr, type, padded.c_str()), "write attribute " + name);
}

namespace {

template <class T>
void writeNumberAttribute(hid_t object, const std::string& name, const std::vector<T>& values, hid_t fileType,
                          hid_t memType) {
  // A single value is stored as a scalar attribute: what readers expect for nx, poissonRatio, ...
  const hsize_t n = values.size();
  Handle space(values.size() == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose,
               "create the dataspace of attribute " + name);
  Handle attr(H5Acreate2(object, name.c_str(), fileType, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
              "create attribute " + name);
  check(H5Awrite(attr, memType, values.data()), "write attribute " + name);
}

herr_t collectAttribute(hid_t, const char* name, const H5A_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

herr_t collectLink(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

}  // namespace

void writeNumbers(hid_t object, const std::string& name, const std::vector<double>& values) {
  writeNumberAttribute(object, name, values, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}
void writeNumbers(hid_t object, const std::string& name, const std::vector<std::int64_t>& values) {
  writeNumberAttribute(object, name, values, H5T_STD_I64LE, H5T_NATIVE_INT64);
}
void writeNumbers(hid_t object, const std::string& name, const std::vector<std::uint64_t>& values) {
  writeNumberAttribute(object, name, values, H5T_STD_U64LE, H5T_NATIVE_UINT64);
}

double readDouble(hid_t object, const std::string& name) {
  Handle attr(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  Handle space(H5Aget_space(attr), H5Sclose, "query attribute " + name);
  if (H5Sget_simple_extent_npoints(space) != 1) throw Error("HDF5: attribute " + name + " is not a single number");
  double v = 0;
  check(H5Aread(attr, H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  return v;
}

std::vector<hsize_t> toDims(const std::vector<std::uint64_t>& shape) { return {shape.begin(), shape.end()}; }

Handle writeDataset(hid_t parent, const std::string& name, const std::vector<std::uint64_t>& shape, const double* data) {
  const auto dims = toDims(shape);
  Handle space(dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
               H5Sclose, "create the dataspace of " + name);
  Handle set(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "create dataset " + name);
  check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset " + name);
  return set;
}

Doubles readDataset(hid_t parent, const std::string& name) {
  Handle set(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  Handle space(H5Dget_space(set), H5Sclose, "query dataset " + name);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) throw Error("HDF5: cannot query the rank of dataset " + name);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  check(H5Sget_simple_extent_dims(space, dims.data(), nullptr), "query the shape of dataset " + name);
  Doubles out;
  out.shape.assign(dims.begin(), dims.end());
  std::size_t count = 1;
  for (hsize_t d : dims) count *= static_cast<std::size_t>(d);
  out.values.resize(count);
  check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data()), "read dataset " + name);
  return out;
}

std::vector<std::string> attributeNames(hid_t object) {
  std::vector<std::string> names;
  check(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectAttribute, &names), "list attributes");
  return names;
}

std::vector<std::string> linkNames(hid_t group) {
  std::vector<std::string> names;
  check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectLink, &names), "list the links of a group");
  return names;
}

}  // namespace peristep::hdf5
