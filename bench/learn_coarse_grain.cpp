// Coarse-grains the LAMMPS output of scripts/md/generate.py (003 Sec. 5 data sets) into the HDF5 layout of
// learning/coarse_data_file.hpp: static sets (train, validation) with cone weights 003:(4) on a 20 x 20
// periodic lattice; fracture sets with the adaptive weights 003:(5)-(9) on h = 5 A (and 3.17 A for the
// training sample). Prints the largest bond strain of every static set (003: below 2%).
//   learn_coarse_grain --manifest FILE --out FILE.h5
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "learning/coarse_data_file.hpp"

using namespace peristep::learning;

namespace {

constexpr double kMass = 12.011;      // amu (LAMMPS input)
constexpr double kThickness = 3.35;   // A, 003 Sec. 5
constexpr double kRadius = 5.0;       // A, coarse-graining radius R (not given in 003)

struct Frame {
  double lo[2], hi[2];
  std::map<std::string, std::vector<double>> column;  // sorted by atom id
};

// LAMMPS text dump: every frame, columns by name, rows sorted by id.
std::vector<Frame> readDump(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<Frame> frames;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: NUMBER OF ATOMS", 0) != 0) continue;
    std::size_t n = 0;
    in >> n;
    std::getline(in, line);
    std::getline(in, line);  // ITEM: BOX BOUNDS
    Frame f;
    for (int d = 0; d < 3; ++d) {
      double lo, hi;
      in >> lo >> hi;
      if (d < 2) f.lo[d] = lo, f.hi[d] = hi;
    }
    std::getline(in, line);
    std::getline(in, line);  // ITEM: ATOMS names...
    std::istringstream header(line.substr(12));
    std::vector<std::string> names;
    for (std::string s; header >> s;) names.push_back(s);
    std::vector<std::vector<double>> rows(n, std::vector<double>(names.size()));
    for (auto& r : rows)
      for (double& v : r) in >> v;
    std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a[0] < b[0]; });
    for (std::size_t c = 0; c < names.size(); ++c)
      for (const auto& r : rows) f.column[names[c]].push_back(r[c]);
    frames.push_back(std::move(f));
  }
  if (frames.empty()) throw std::runtime_error("no frame in " + path);
  return frames;
}

// Largest |bond strain| over reference bonds shorter than 1.7 A (minimum image in a periodic box).
double maxBondStrain(const std::vector<double>& X, const std::vector<double>& Y, const std::vector<double>& U,
                     double Lx, double Ly) {
  double worst = 0;
  for (std::size_t a = 0; a < X.size(); ++a)
    for (std::size_t b = a + 1; b < X.size(); ++b) {
      double dx = X[b] - X[a], dy = Y[b] - Y[a];
      dx -= Lx * std::round(dx / Lx), dy -= Ly * std::round(dy / Ly);
      const double r = std::hypot(dx, dy);
      if (r > 1.7) continue;
      const double s = std::hypot(dx + U[2 * b] - U[2 * a], dy + U[2 * b + 1] - U[2 * a + 1]) / r - 1;
      worst = std::max(worst, std::abs(s));
    }
  return worst;
}

CoarseDataSet staticSet(const std::vector<std::string>& files, double& strain) {
  CoarseDataSet set{{}, 0.0, kThickness, kRadius, {}};
  std::unique_ptr<CoarseGraining> cg;
  strain = 0;
  for (const std::string& path : files) {
    const Frame f = readDump(path).back();
    const std::vector<double>&X = f.column.at("f_ref[1]"), &Y = f.column.at("f_ref[2]");
    const double Lx = f.hi[0] - f.lo[0], Ly = f.hi[1] - f.lo[1];
    if (!cg) {
      set.grid = CoarseGrid{20, 20, f.lo[0] + Lx / 40, f.lo[1] + Ly / 40, Lx / 20, Ly / 20, true};
      cg = std::make_unique<CoarseGraining>(set.grid, X, Y, std::vector<double>(X.size(), kMass), kRadius, kThickness);
    }
    std::vector<double> U, B;
    for (std::size_t e = 0; e < X.size(); ++e) {
      U.push_back(f.column.at("v_ux")[e]), U.push_back(f.column.at("v_uy")[e]);
      B.push_back(f.column.at("v_bxf")[e]), B.push_back(f.column.at("v_byf")[e]);
    }
    strain = std::max(strain, maxBondStrain(X, Y, U, Lx, Ly));
    set.samples.push_back(cg->average(U, B, false));
  }
  return set;
}

CoarseDataSet fractureSet(const std::vector<Frame>& frames, double h, int frameSteps) {
  const auto n = static_cast<std::size_t>(std::floor(100.0 / h));
  const double x0 = -0.5 * h * static_cast<double>(n - 1);
  CoarseDataSet set{CoarseGrid{n, n, x0, x0, h, h, false}, frameSteps * 0.5e-15, kThickness, kRadius, {}};
  const std::vector<double>&X = frames[0].column.at("f_ref[1]"), &Y = frames[0].column.at("f_ref[2]");
  const CoarseGraining cg(set.grid, X, Y, std::vector<double>(X.size(), kMass), kRadius, kThickness);
  for (const Frame& f : frames) {
    std::vector<double> U, B;
    for (std::size_t e = 0; e < X.size(); ++e) {
      U.push_back(f.column.at("x")[e] - X[e]), U.push_back(f.column.at("y")[e] - Y[e]);
      B.push_back(f.column.at("v_bx")[e]), B.push_back(f.column.at("v_by")[e]);
    }
    set.samples.push_back(cg.average(U, B, true));
  }
  return set;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Coarse-grain the MD data of scripts/md/generate.py into HDF5 (003:(4)-(12))"};
  std::string manifest, out;
  app.add_option("--manifest", manifest, "manifest written by generate.py")->required();
  app.add_option("--out", out, "HDF5 file")->required();
  int frameSteps = 99;
  app.add_option("--frame-steps", frameSteps, "MD steps of 0.5 fs between the fracture sets' frames");
  if (const auto code = peristep::bench::parseArguments(app, argc, argv)) return *code;
  try {
    const auto t0 = std::chrono::steady_clock::now();
    std::ifstream in(manifest);
    if (!in) throw std::runtime_error("cannot open " + manifest);
    CoarseDataFile data;
    std::map<std::string, std::vector<std::string>> files;
    for (std::string kind, name, value; in >> kind >> name >> value;) {
      if (kind == "constant")
        data.constants[name] = std::stod(value);
      else
        files[kind].push_back(value);
    }
    for (const char* s : {"train", "validation"}) {
      if (!files.count(s)) continue;
      double strain = 0;
      data.sets[s] = staticSet(files[s], strain);
      std::cout << s << ": " << files[s].size() << " samples, largest bond strain " << strain << "\n";
    }
    for (const char* s : {"fracture_train", "fracture_test"}) {
      if (!files.count(s)) continue;
      const std::vector<Frame> frames = readDump(files[s].front());
      data.sets[s] = fractureSet(frames, 5.0, frameSteps);
      if (std::string(s) == "fracture_train") data.sets["fracture_train_fine"] = fractureSet(frames, 3.17, frameSteps);
      std::cout << s << ": " << frames.size() << " frames\n";
    }
    writeCoarseData(out, data);
    std::cout << "wrote " << out << " in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
  } catch (const std::exception& e) {
    std::cerr << "learn_coarse_grain: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
