#include "result_files.hpp"

#include <system_error>

#include "host_errors.hpp"
#include "output_lock.hpp"
#include "xdmf_writer.hpp"

namespace peristep::host {

namespace fs = std::filesystem;

namespace {

fs::path xmfOf(const fs::path& h5) { return fs::path(h5).replace_extension(".xmf"); }

}  // namespace

fs::path partialName(const fs::path& file) {
  fs::path p = file;
  p.replace_filename(file.stem().string() + ".partial" + file.extension().string());
  return p;
}

ResultFiles::ResultFiles(const fs::path& hdf5File, const ResultLayout& layout)
    : final_(hdf5File), partial_(partialName(hdf5File)), layout_(layout) {
  requireOutputDirectory(hdf5File);
  writer_ = std::make_unique<Hdf5Writer>(partial_, layout);
}

ResultFiles::~ResultFiles() {
  if (done_) return;
  try {
    abandon();
  } catch (...) {  // a destructor must not throw; the partial files are left for the user to inspect
  }
}

fs::path ResultFiles::xdmfFile() const { return xmfOf(final_); }

void ResultFiles::append(const StepValues& step) {
  writer_->append(step);
  writeXdmf(xmfOf(partial_), layout_, partial_.filename().string(), writer_->history());
}

void ResultFiles::commit() {
  const std::vector<StepScalars> steps = writer_->history();
  writer_->close();
  std::error_code ec;
  fs::rename(partial_, final_, ec);
  if (ec) throw RunError(final_.string() + ": cannot move the results into place: " + ec.message());
  writeXdmf(xmfOf(final_), layout_, final_.filename().string(), steps);
  fs::remove(xmfOf(partial_), ec);
  done_ = true;
}

fs::path ResultFiles::abandon() {
  done_ = true;
  const bool keep = writer_->steps() > 0;
  writer_->close();
  if (keep) return partial_;
  std::error_code ec;
  fs::remove(partial_, ec);
  fs::remove(xmfOf(partial_), ec);
  return {};
}

}  // namespace peristep::host
