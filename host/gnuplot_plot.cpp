#include "gnuplot_plot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace peristep::host {

namespace {

// gnuplot single-quoted string: a quote is written twice.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

}  // namespace

bool gnuplotAvailable() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((std::filesystem::path(dir) / "gnuplot").c_str(), X_OK) == 0) return true;
  return false;
}

std::string plotConvergence(const std::filesystem::path& csv, const std::filesystem::path& png, const PowerFit& fit,
                            const std::string& title) {
  std::ostringstream script;
  script << "set terminal pngcairo size 1100,450 font ',10'\n"
         << "set output " << quoted(png.string()) << "\n"
         << "set datafile separator ','\n"
         << "set logscale xy\n"
         << "set format xy '%.0e'\n"
         << "set grid\n"
         << "set key bottom right\n"
         << "set ylabel 'L2 error'\n"
         << "set multiplot layout 1,2 title " << quoted(title) << " noenhanced\n"
         << "set xlabel 'grid spacing h'\n";
  // Columns of the CSV: 4 = h, 6 = error_l2, 8 = wall_s.
  script << "plot " << quoted(csv.string()) << " skip 1 using 4:6 with linespoints pt 7 title 'errorL2'";
  if (std::isfinite(fit.order))
    script << ", " << fit.constant << " * x**" << fit.order << " with lines dashtype 2 title sprintf('fit: h^{%.2f}', "
           << fit.order << ")";
  script << "\n"
         << "set xlabel 'wall time per level [s]'\n"
         << "plot " << quoted(csv.string()) << " skip 1 using 8:6 with linespoints pt 7 title 'errorL2'\n"
         << "unset multiplot\n";

  std::FILE* pipe = popen("gnuplot", "w");
  if (!pipe) return "cannot start gnuplot";
  const std::string text = script.str();
  std::fwrite(text.data(), 1, text.size(), pipe);
  const int status = pclose(pipe);
  if (status != 0) return "gnuplot failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  return "";
}

}  // namespace peristep::host
