#pragma once
// gnuplot (pngcairo) as the host's drawing tool, when it is installed: a missing picture is worth a
// note, not a failed run. The plots and pictures themselves are in gnuplot_plot, run_picture,
// run_history and sample_plot.
#include <cstddef>
#include <filesystem>
#include <string>

namespace peristep::host {

// Looks for an executable `gnuplot` on PATH.
bool gnuplotAvailable();

// gnuplot single-quoted string: a quote is written twice.
std::string gnuplotQuoted(const std::string& s);

// Runs `script` through `gnuplot` (its messages go to our stderr); returns its complaint or "".
std::string runGnuplot(const std::string& script);
// The same for a script that writes `picture`: a failed or empty picture is removed (gnuplot creates
// the file before it draws), so a picture on disk is one that was drawn.
std::string runGnuplot(const std::string& script, const std::filesystem::path& picture);

// A temporary file of raw bytes that a script reads (`binary array=...`), removed with the object.
class GnuplotData {
 public:
  GnuplotData(const void* bytes, std::size_t size);
  ~GnuplotData();
  GnuplotData(const GnuplotData&) = delete;
  GnuplotData& operator=(const GnuplotData&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace peristep::host
