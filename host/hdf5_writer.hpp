#pragma once
// Results of a run in HDF5 (C API), readable while the run goes on and valid after any step:
//   /grid/<name>       constant arrays on the grid (x, y) [ny][nx]
//   /time              communication points reached, [steps]
//   /inputs/<name>     the ramped input, [steps]
//   /scalars/<name>    scalar outputs, [steps]
//   /fields/<name>     array outputs, [steps][shape...] (ux, uy, damage: [steps][ny][nx]),
//                      chunked per step, shuffled and deflate-compressed
//   /xdmf/xy, /xdmf/step_<k>/<field>   views for the XDMF file (virtual datasets, no data of their own:
//                      see result_layout.hpp)
//   attributes: on "/" the run's provenance, on /parameters every parameter as used,
//               on each dataset its unit and description.
// Every time-dependent dataset is extendible along steps; the file is flushed after each step.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "hdf5_io.hpp"
#include "result_layout.hpp"

namespace peristep::host {

class Hdf5Writer {
 public:
  // Creates (truncates) the file and writes the grid and attributes. Throws RunError.
  Hdf5Writer(const std::filesystem::path& file, const ResultLayout& layout);

  // Throws RunError.
  void append(const StepValues& step);
  std::uint64_t steps() const { return steps_; }
  const std::vector<StepScalars>& history() const { return history_; }
  // Closes the file (also done by the destructor); afterwards nothing may be appended.
  void close();

 private:
  std::filesystem::path file_;
  const ResultLayout& layout_;
  hdf5::Handle fileId_;
  std::vector<hdf5::Handle> series_;  // time, input (if any), scalars, fields: in this order
  std::uint64_t steps_ = 0;
  std::vector<StepScalars> history_;
};

}  // namespace peristep::host
