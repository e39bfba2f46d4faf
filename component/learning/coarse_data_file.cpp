#include "learning/coarse_data_file.hpp"

#include "core/errors.hpp"
#include "hdf5_io.hpp"

namespace peristep::learning {

namespace {

// The values of dataset `name`, checked against the shape that the set's grid and sample count give it.
std::vector<double> shaped(hdf5::Doubles d, const std::string& name, const std::vector<std::uint64_t>& shape) {
  if (d.shape != shape) {
    std::string got, expected;
    for (std::uint64_t e : d.shape) got += (got.empty() ? "" : " x ") + std::to_string(e);
    for (std::uint64_t e : shape) expected += (expected.empty() ? "" : " x ") + std::to_string(e);
    throw hdf5::Error("HDF5: dataset " + name + " is " + got + ", expected " + expected);
  }
  return std::move(d.values);
}

}  // namespace

void writeCoarseData(const std::string& path, const CoarseDataFile& data) {
  hdf5::Handle file = hdf5::createFile(path);
  for (const auto& [name, v] : data.constants) hdf5::writeNumbers(file, name, std::vector<double>{v});
  for (const auto& [name, set] : data.sets) {
    const hdf5::Handle g = hdf5::createGroup(file, name);
    const CoarseGrid& gr = set.grid;
    const std::pair<const char*, double> attrs[] = {
        {"nx", double(gr.nx)}, {"ny", double(gr.ny)}, {"x0", gr.x0}, {"y0", gr.y0}, {"hx", gr.hx}, {"hy", gr.hy},
        {"periodic", gr.periodic ? 1.0 : 0.0}, {"frame_interval", set.frameInterval}, {"thickness", set.thickness},
        {"radius", set.radius}};
    for (const auto& [k, v] : attrs) hdf5::writeNumbers(g, k, std::vector<double>{v});
    std::vector<double> rho, u, b;
    for (const CoarseFields& f : set.samples) {
      rho.insert(rho.end(), f.rho.begin(), f.rho.end());
      u.insert(u.end(), f.u.begin(), f.u.end());
      b.insert(b.end(), f.b.begin(), f.b.end());
    }
    const std::uint64_t S = set.samples.size(), N = gr.size();
    hdf5::writeDataset(g, "rho", {S, N}, rho.data());
    hdf5::writeDataset(g, "u", {S, N, 2}, u.data());
    hdf5::writeDataset(g, "b", {S, N, 2}, b.data());
  }
  file.close("close " + path);
}

CoarseDataFile readCoarseData(const std::string& path) {
  hdf5::Handle file;
  try {
    file = hdf5::openFile(path);
  } catch (const hdf5::Error&) {
    throw InvalidInput("coarse-grained data: cannot open " + path);
  }
  CoarseDataFile data;
  for (const std::string& n : hdf5::attributeNames(file)) data.constants[n] = hdf5::readDouble(file, n);
  for (const std::string& n : hdf5::linkNames(file)) {
    const hdf5::Handle g = hdf5::openGroup(file, n);
    CoarseDataSet set;
    set.grid.nx = static_cast<std::size_t>(hdf5::readDouble(g, "nx"));
    set.grid.ny = static_cast<std::size_t>(hdf5::readDouble(g, "ny"));
    set.grid.x0 = hdf5::readDouble(g, "x0"), set.grid.y0 = hdf5::readDouble(g, "y0");
    set.grid.hx = hdf5::readDouble(g, "hx"), set.grid.hy = hdf5::readDouble(g, "hy");
    set.grid.periodic = hdf5::readDouble(g, "periodic") != 0;
    set.frameInterval = hdf5::readDouble(g, "frame_interval");
    set.thickness = hdf5::readDouble(g, "thickness");
    set.radius = hdf5::readDouble(g, "radius");
    hdf5::Doubles rhoData = hdf5::readDataset(g, "rho");
    const std::uint64_t N = set.grid.size(), S = rhoData.shape.empty() ? 0 : rhoData.shape[0];
    const std::vector<double> rho = shaped(std::move(rhoData), "rho", {S, N}),
                              u = shaped(hdf5::readDataset(g, "u"), "u", {S, N, 2}),
                              b = shaped(hdf5::readDataset(g, "b"), "b", {S, N, 2});
    for (std::size_t s = 0; s < S; ++s)
      set.samples.push_back({{rho.begin() + s * N, rho.begin() + (s + 1) * N},
                             {u.begin() + 2 * s * N, u.begin() + 2 * (s + 1) * N},
                             {b.begin() + 2 * s * N, b.begin() + 2 * (s + 1) * N}});
    data.sets[n] = std::move(set);
  }
  return data;
}

}  // namespace peristep::learning
