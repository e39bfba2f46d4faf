#include "hdf5_support.hpp"

#include <algorithm>
#include <type_traits>

#include "host_errors.hpp"

namespace peristep::host {

Handle::Handle(hid_t id, herr_t (*closer)(hid_t), const std::string& what) : id_(id), closer_(closer) {
  if (id_ < 0) throw RunError("HDF5: cannot " + what);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw RunError("HDF5: cannot " + what);
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
void writeNumbers(hid_t object, const std::string& name, const std::vector<T>& values, hid_t fileType, hid_t memType) {
  // A single value is stored as a scalar attribute: what readers expect for nx, poissonRatio, ...
  const hsize_t n = values.size();
  Handle space(values.size() == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose,
               "create the dataspace of attribute " + name);
  Handle attr(H5Acreate2(object, name.c_str(), fileType, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
              "create attribute " + name);
  check(H5Awrite(attr, memType, values.data()), "write attribute " + name);
}

}  // namespace

void writeAttribute(hid_t object, const Attribute& a) {
  std::visit(
      [&](const auto& v) {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, std::string>) writeString(object, a.name, v);
        else if constexpr (std::is_same_v<V, std::vector<double>>) writeNumbers(object, a.name, v, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
        else if constexpr (std::is_same_v<V, std::vector<std::int64_t>>) writeNumbers(object, a.name, v, H5T_STD_I64LE, H5T_NATIVE_INT64);
        else writeNumbers(object, a.name, v, H5T_STD_U64LE, H5T_NATIVE_UINT64);
      },
      a.value);
}

void describe(hid_t object, const ArrayInfo& info) {
  if (!info.unit.empty()) writeString(object, "unit", info.unit);
  if (!info.description.empty()) writeString(object, "description", info.description);
}

std::vector<hsize_t> toDims(const std::vector<std::uint64_t>& shape) { return {shape.begin(), shape.end()}; }

void writeDataset(hid_t parent, const std::string& name, const std::vector<std::uint64_t>& shape, const double* data) {
  const auto dims = toDims(shape);
  Handle space(dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
               H5Sclose, "create the dataspace of " + name);
  Handle set(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "create dataset " + name);
  check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + name);
}

hid_t createGroup(hid_t parent, const std::string& path) {
  Handle props(H5Pcreate(H5P_LINK_CREATE), H5Pclose, "create link properties");
  check(H5Pset_create_intermediate_group(props, 1), "allow intermediate groups");
  const hid_t id = H5Gcreate2(parent, path.c_str(), props, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) throw RunError("HDF5: cannot create group " + path);
  return id;
}

}  // namespace peristep::host
