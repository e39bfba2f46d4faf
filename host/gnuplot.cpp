#include "gnuplot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "host_errors.hpp"

namespace peristep::host {

bool gnuplotAvailable() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((std::filesystem::path(dir) / "gnuplot").c_str(), X_OK) == 0) return true;
  return false;
}

std::string gnuplotQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string runGnuplot(const std::string& script) {
  std::FILE* pipe = popen("gnuplot", "w");
  if (!pipe) return "cannot start gnuplot";
  std::fwrite(script.data(), 1, script.size(), pipe);
  const int status = pclose(pipe);
  if (status != 0) return "gnuplot failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  return "";
}

std::string runGnuplot(const std::string& script, const std::filesystem::path& picture) {
  std::string problem = runGnuplot(script);
  std::error_code ec;
  const auto size = std::filesystem::file_size(picture, ec);
  if (problem.empty() && (ec || size == 0)) problem = "gnuplot wrote no picture";
  if (!problem.empty()) std::filesystem::remove(picture, ec);
  return problem;
}

GnuplotData::GnuplotData(const void* bytes, std::size_t size) {
  std::string name = (std::filesystem::temp_directory_path() / "peristep_plot_XXXXXX").string();
  const int fd = mkstemp(name.data());
  if (fd < 0) throw RunError("cannot create a temporary file for gnuplot in " + std::filesystem::temp_directory_path().string());
  path_ = name;
  const bool written = write(fd, bytes, size) == static_cast<ssize_t>(size);
  close(fd);
  if (!written) {
    std::filesystem::remove(path_);
    throw RunError(path_.string() + ": cannot write the data for gnuplot");
  }
}

GnuplotData::~GnuplotData() {
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

}  // namespace peristep::host
