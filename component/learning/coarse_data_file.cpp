#include "learning/coarse_data_file.hpp"

#include <hdf5.h>

#include "core/errors.hpp"

namespace peristep::learning {

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw SolverFailure("HDF5: cannot " + what);
}
hid_t checked(hid_t id, const std::string& what) {
  if (id < 0) throw SolverFailure("HDF5: cannot " + what);
  return id;
}

void writeScalar(hid_t obj, const std::string& name, double v) {
  const hid_t space = checked(H5Screate(H5S_SCALAR), "create a dataspace");
  const hid_t a = checked(H5Acreate2(obj, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT),
                          "create attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_DOUBLE, &v), "write attribute " + name);
  H5Aclose(a);
  H5Sclose(space);
}

double readScalar(hid_t obj, const std::string& name) {
  const hid_t a = checked(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "open attribute " + name);
  double v = 0;
  const herr_t s = H5Aread(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a);
  check(s, "read attribute " + name);
  return v;
}

void writeArray(hid_t group, const std::string& name, const std::vector<hsize_t>& dims, const std::vector<double>& v) {
  const hid_t space = checked(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), "create a dataspace");
  const hid_t d = checked(H5Dcreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                          "create dataset " + name);
  check(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), "write dataset " + name);
  H5Dclose(d);
  H5Sclose(space);
}

std::vector<double> readArray(hid_t group, const std::string& name, std::size_t expected) {
  const hid_t d = checked(H5Dopen2(group, name.c_str(), H5P_DEFAULT), "open dataset " + name);
  const hid_t space = H5Dget_space(d);
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  H5Sclose(space);
  std::vector<double> v(n);
  const herr_t s = n == expected ? H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) : -1;
  H5Dclose(d);
  check(s, "read dataset " + name + " (size " + std::to_string(n) + ", expected " + std::to_string(expected) + ")");
  return v;
}

}  // namespace

void writeCoarseData(const std::string& path, const CoarseDataFile& data) {
  const hid_t file = checked(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "create " + path);
  for (const auto& [name, v] : data.constants) writeScalar(file, name, v);
  for (const auto& [name, set] : data.sets) {
    const hid_t g = checked(H5Gcreate2(file, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "create group " + name);
    const CoarseGrid& gr = set.grid;
    const std::pair<const char*, double> attrs[] = {
        {"nx", double(gr.nx)}, {"ny", double(gr.ny)}, {"x0", gr.x0}, {"y0", gr.y0}, {"hx", gr.hx}, {"hy", gr.hy},
        {"periodic", gr.periodic ? 1.0 : 0.0}, {"frame_interval", set.frameInterval}, {"thickness", set.thickness},
        {"radius", set.radius}};
    for (const auto& [k, v] : attrs) writeScalar(g, k, v);
    std::vector<double> rho, u, b;
    for (const CoarseFields& f : set.samples) {
      rho.insert(rho.end(), f.rho.begin(), f.rho.end());
      u.insert(u.end(), f.u.begin(), f.u.end());
      b.insert(b.end(), f.b.begin(), f.b.end());
    }
    const hsize_t S = set.samples.size(), N = gr.size();
    writeArray(g, "rho", {S, N}, rho);
    writeArray(g, "u", {S, N, 2}, u);
    writeArray(g, "b", {S, N, 2}, b);
    H5Gclose(g);
  }
  check(H5Fclose(file), "close " + path);
}

namespace {
herr_t collectAttribute(hid_t, const char* name, const H5A_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}
herr_t collectGroup(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}
}  // namespace

CoarseDataFile readCoarseData(const std::string& path) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw InvalidInput("coarse-grained data: cannot open " + path);
  CoarseDataFile data;
  try {
    std::vector<std::string> names;
    check(H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectAttribute, &names), "list attributes");
    for (const std::string& n : names) data.constants[n] = readScalar(file, n);
    names.clear();
    check(H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectGroup, &names), "list groups");
    for (const std::string& n : names) {
      const hid_t g = checked(H5Gopen2(file, n.c_str(), H5P_DEFAULT), "open group " + n);
      CoarseDataSet set;
      set.grid.nx = static_cast<std::size_t>(readScalar(g, "nx"));
      set.grid.ny = static_cast<std::size_t>(readScalar(g, "ny"));
      set.grid.x0 = readScalar(g, "x0"), set.grid.y0 = readScalar(g, "y0");
      set.grid.hx = readScalar(g, "hx"), set.grid.hy = readScalar(g, "hy");
      set.grid.periodic = readScalar(g, "periodic") != 0;
      set.frameInterval = readScalar(g, "frame_interval");
      set.thickness = readScalar(g, "thickness");
      set.radius = readScalar(g, "radius");
      const hid_t d = checked(H5Dopen2(g, "rho", H5P_DEFAULT), "open rho");
      const hid_t space = H5Dget_space(d);
      hsize_t dims[2] = {0, 0};
      H5Sget_simple_extent_dims(space, dims, nullptr);
      H5Sclose(space);
      H5Dclose(d);
      const std::size_t S = dims[0], N = set.grid.size();
      const std::vector<double> rho = readArray(g, "rho", S * N), u = readArray(g, "u", 2 * S * N),
                                b = readArray(g, "b", 2 * S * N);
      for (std::size_t s = 0; s < S; ++s)
        set.samples.push_back({{rho.begin() + s * N, rho.begin() + (s + 1) * N},
                               {u.begin() + 2 * s * N, u.begin() + 2 * (s + 1) * N},
                               {b.begin() + 2 * s * N, b.begin() + 2 * (s + 1) * N}});
      H5Gclose(g);
      data.sets[n] = std::move(set);
    }
  } catch (...) {
    H5Fclose(file);
    throw;
  }
  H5Fclose(file);
  return data;
}

}  // namespace peristep::learning
