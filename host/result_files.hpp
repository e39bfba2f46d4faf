#pragma once
// Where a run's results go. While the run lasts they are written to "<name>.partial.h5" and
// "<name>.partial.xmf" next to the requested file; only a successful run renames them onto the
// requested names. So a failing run never corrupts the results of an earlier one, and the steps it
// did finish stay readable (HDF5 flushed, XDMF rewritten after every step). The caller holds the
// output's OutputLock, so there is one writer per name.
#include <filesystem>
#include <memory>

#include "hdf5_writer.hpp"

namespace peristep::host {

class ResultFiles {
 public:
  ResultFiles(const std::filesystem::path& hdf5File, const ResultLayout& layout);
  ~ResultFiles();  // abandons the run if neither commit() nor abandon() was called
  ResultFiles(const ResultFiles&) = delete;
  ResultFiles& operator=(const ResultFiles&) = delete;

  void append(const StepValues& step);
  std::uint64_t steps() const { return writer_->steps(); }
  const std::vector<StepScalars>& history() const { return writer_->history(); }

  // Success: the partial files become <name>.h5 and <name>.xmf.
  void commit();
  // Failure: the requested names are left as they were. Returns the partial HDF5 file when it holds
  // at least one step (it is kept, with its XDMF), otherwise removes the partial files and returns {}.
  std::filesystem::path abandon();

  const std::filesystem::path& hdf5File() const { return final_; }
  std::filesystem::path xdmfFile() const;

 private:
  std::filesystem::path final_, partial_;
  const ResultLayout& layout_;
  std::unique_ptr<Hdf5Writer> writer_;
  bool done_ = false;
};

// "<dir>/<stem>.partial<ext>": the in-progress name of a result file.
std::filesystem::path partialName(const std::filesystem::path& file);

}  // namespace peristep::host
