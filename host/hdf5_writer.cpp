#include "hdf5_writer.hpp"

#include <string>

#include "hdf5_support.hpp"
#include "host_errors.hpp"

namespace peristep::host {

using hdf5::check;
using hdf5::Handle;
using hdf5::toDims;

namespace {

// A dataset [0][shape...] that grows by one record per step.
Handle createSeries(hid_t parent, const std::string& path, const std::vector<std::uint64_t>& itemShape) {
  std::vector<hsize_t> dims{0}, maxDims{H5S_UNLIMITED}, chunk{1};
  for (hsize_t e : toDims(itemShape)) dims.push_back(e), maxDims.push_back(e), chunk.push_back(e);
  const bool scalarSeries = itemShape.empty();
  if (scalarSeries) chunk[0] = 256;  // a few KB per chunk: time series are short rows of doubles
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), maxDims.data()), H5Sclose,
               "create the dataspace of " + path);
  Handle props(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "create dataset properties");
  check(H5Pset_chunk(props, static_cast<int>(chunk.size()), chunk.data()), "chunk " + path);
  if (!scalarSeries) {
    check(H5Pset_shuffle(props), "shuffle " + path);  // byte shuffling roughly doubles deflate's gain on doubles
    check(H5Pset_deflate(props, 4), "compress " + path);
  }
  return {H5Dcreate2(parent, path.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, props, H5P_DEFAULT), H5Dclose,
          "create dataset " + path};
}

void appendRecord(hid_t dataset, std::uint64_t step, const double* data, const std::string& what) {
  Handle fileSpace0(H5Dget_space(dataset), H5Sclose, "query " + what);
  const int rank = H5Sget_simple_extent_ndims(fileSpace0);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(fileSpace0, dims.data(), nullptr);
  dims[0] = step + 1;
  check(H5Dset_extent(dataset, dims.data()), "extend " + what);

  Handle fileSpace(H5Dget_space(dataset), H5Sclose, "query " + what);
  std::vector<hsize_t> start(dims.size(), 0), count = dims;
  start[0] = step;
  count[0] = 1;
  check(H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr), "select in " + what);
  Handle memSpace(H5Screate_simple(rank, count.data(), nullptr), H5Sclose, "create a memory dataspace");
  check(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, memSpace, fileSpace, H5P_DEFAULT, data), "write " + what);
}

// One block of a virtual dataset: `count` elements at `start` of the view are those at
// `sourceStart` of the dataset `source` in this same file, taken in row-major order.
struct ViewBlock {
  std::vector<hsize_t> start, count;
  std::string source;
  std::vector<hsize_t> sourceStart, sourceCount;
};

void createView(hid_t file, const std::string& path, const std::vector<hsize_t>& dims, const std::vector<ViewBlock>& blocks) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose,
               "create the dataspace of " + path);
  Handle props(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "create dataset properties");
  for (const ViewBlock& b : blocks) {
    Handle view(H5Scopy(space), H5Sclose, "copy a dataspace");
    check(H5Sselect_hyperslab(view, H5S_SELECT_SET, b.start.data(), nullptr, b.count.data(), nullptr), "select in " + path);
    // The source's current extent: a step's view is created right after the step is written.
    Handle sourceSet(H5Dopen2(file, b.source.c_str(), H5P_DEFAULT), H5Dclose, "open " + b.source);
    Handle source(H5Dget_space(sourceSet), H5Sclose, "query " + b.source);
    check(H5Sselect_hyperslab(source, H5S_SELECT_SET, b.sourceStart.data(), nullptr, b.sourceCount.data(), nullptr),
          "select in " + b.source);
    check(H5Pset_virtual(props, view, ".", b.source.c_str(), source), "map " + path + " to " + b.source);
  }
  Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose, "create link properties");
  check(H5Pset_create_intermediate_group(links, 1), "allow intermediate groups");
  Handle set(H5Dcreate2(file, path.c_str(), H5T_IEEE_F64LE, space, links, props, H5P_DEFAULT), H5Dclose, "create " + path);
}

}  // namespace

Hdf5Writer::Hdf5Writer(const std::filesystem::path& file, const ResultLayout& layout) : file_(file), layout_(layout) {
  try {
    fileId_ = hdf5::createFile(file.string());
  } catch (const hdf5::Error&) {
    throw RunError(file.string() + ": cannot create the HDF5 file");
  }
  // On a failure the handles made so far close with the half-built writer.
  asRunError([&] {
    for (const Attribute& a : layout.fileAttributes) writeAttribute(fileId_, a);
    const Handle parameters = hdf5::createGroup(fileId_, "/parameters");
    for (const Attribute& a : layout.parameterAttributes) writeAttribute(parameters, a);

    const Handle grid = hdf5::createGroup(fileId_, "/grid");
    for (std::size_t i = 0; i < layout.constantArrays.size(); ++i) {
      const ArrayInfo& a = layout.constantArrays[i];
      describe(hdf5::writeDataset(grid, a.name, a.shape, layout.constantValues[i].data()), a);
    }

    // x and y interleaved for the XDMF geometry.
    const hsize_t ny = layout.ny, nx = layout.nx;
    createView(fileId_, xdmfGeometryPath(), {ny, nx, 2},
               {{{0, 0, 0}, {ny, nx, 1}, "/grid/x", {0, 0}, {ny, nx}}, {{0, 0, 1}, {ny, nx, 1}, "/grid/y", {0, 0}, {ny, nx}}});

    series_.push_back(createSeries(fileId_, "/time", {}));
    if (!layout.inputName.empty()) {
      const Handle inputs = hdf5::createGroup(fileId_, "/inputs");
      series_.push_back(createSeries(inputs, layout.inputName, {}));
    }
    const Handle scalars = hdf5::createGroup(fileId_, "/scalars");
    for (const ArrayInfo& s : layout.scalars) {
      series_.push_back(createSeries(scalars, s.name, {}));
      describe(series_.back(), s);
    }
    const Handle fields = hdf5::createGroup(fileId_, "/fields");
    for (const ArrayInfo& f : layout.fields) {
      series_.push_back(createSeries(fields, f.name, f.shape));
      describe(series_.back(), f);
    }
    check(H5Fflush(fileId_, H5F_SCOPE_GLOBAL), "flush " + file.string());
  });
}

void Hdf5Writer::close() {
  series_.clear();
  fileId_ = {};
}

void Hdf5Writer::append(const StepValues& step) {
  if (fileId_ < 0) throw RunError(file_.string() + ": appending to a closed HDF5 file");
  if (step.scalars.size() != layout_.scalars.size() || step.fields.size() != layout_.fields.size())
    throw RunError(file_.string() + ": a step does not match the layout of the file");
  asRunError([&] {
    std::size_t k = 0;
    appendRecord(series_[k++], steps_, &step.time, "/time");
    if (!layout_.inputName.empty()) appendRecord(series_[k++], steps_, &step.input, "/inputs/" + layout_.inputName);
    for (std::size_t i = 0; i < layout_.scalars.size(); ++i)
      appendRecord(series_[k++], steps_, &step.scalars[i], "/scalars/" + layout_.scalars[i].name);
    for (std::size_t i = 0; i < layout_.fields.size(); ++i) {
      if (step.fields[i].size() != elementCount(layout_.fields[i].shape))
        throw RunError(file_.string() + ": field " + layout_.fields[i].name + " changed its size");
      appendRecord(series_[k++], steps_, step.fields[i].data(), "/fields/" + layout_.fields[i].name);
    }
    for (const ArrayInfo& f : layout_.fields) {
      if (!layout_.onGrid(f)) continue;
      const hsize_t ny = layout_.ny, nx = layout_.nx;
      createView(fileId_, xdmfFieldPath(steps_, f.name), {ny, nx},
                 {{{0, 0}, {ny, nx}, "/fields/" + f.name, {steps_, 0, 0}, {1, ny, nx}}});
    }
    // Flushed per step: whatever the next step does, the steps already written stay readable.
    check(H5Fflush(fileId_, H5F_SCOPE_GLOBAL), "flush " + file_.string());
  });
  ++steps_;
  history_.push_back({step.time, step.input, step.scalars});
}

}  // namespace peristep::host
