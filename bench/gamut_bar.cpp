// The 1D stochastic deformation-gamut bar of 002 (Desai): cyclic n' and K' over realizations beside
// 002 Table 1 and the classical Masing baseline, their convergence in realizations and bonds, their
// sensitivity to the scatter of 002:(26), and the mean monotonic curve against Ramberg-Osgood.
//
//   gamut_bar [--material 1|2|both] [--grid uniform|stochastic|both] [--realizations 30] [--bonds 500]
//             [--steps 4] [--seed 2023] [--skip-table] [--convergence] [--sensitivity]
//             [--monotonic N] [--csv curve] [--png curve.png]
//
// --convergence: n', K' of Material 1 on the uniform grid for 30, 100, 300 realizations (prefixes of
// one 300-realization run) and for 125, 250, 500, 1000 bonds. --sensitivity: the same for scatter
// denominators 5, 10, 20, 40 and Weibull shapes 1, 2, 4. --monotonic N: the 002 force ramp (0.01 N,
// +1% per step, to eps_f) on N realizations per material and grid; --csv PREFIX writes
// PREFIX_m<material>_<grid>.csv (stress, mean strain, Ramberg-Osgood strain), --png draws them.
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "core/timer.hpp"
#include "geometry/bar_grid.hpp"
#include "gnuplot.hpp"
#include "scenes/gamut_study.hpp"
#include "solvers/gamut_bar_solver.hpp"

using namespace peristep;

namespace {

// 002 Table 1 (means over 30 realizations) and the material's deterministic / experimental values.
struct Reference {
  double stochasticN, uniformN, stochasticK, uniformK, deterministicN, deterministicK;
  const char* experiment;
};
const Reference kTable1[2] = {
    {0.0777, 0.0612, 774.1596, 774.4350, 0.06244, 791.6, "n' 0.0662, K' 792.8 MPa"},
    {0.0381, 0.0481, 1032.3, 1091.1, 0.04762, 1105.4, "n' 0.0484, K' 1340.5-1537.6 MPa"},
};

double loadAverage() {
  std::ifstream in("/proc/loadavg");
  double one = 0;
  in >> one;
  return one;
}

GamutBarSpec barSpec(int material, bool stochasticGrid, int bonds, std::uint64_t seed) {
  GamutBarSpec spec;
  spec.material = material == 1 ? gamutMaterial1() : gamutMaterial2();
  spec.gridJitter = stochasticGrid ? kStochasticGridJitter : 0.0;
  spec.bonds = bonds;
  spec.seed = seed;
  return spec;
}

struct Timed {
  GamutStudy study;
  double seconds, load;
};
Timed run(const GamutStudySpec& spec) {
  Stopwatch clock;
  GamutStudy study = runGamutStudy(spec);
  return {std::move(study), clock.seconds(), loadAverage()};
}

void printRow(const char* label, const Timed& t, std::size_t count) {
  const GamutStudy& s = t.study;
  int reruns = 0;
  for (const GamutRealization& r : s.runs) reruns += r.reruns;
  std::printf("%-28s %5zu  n' %.5f +- %.5f  K' %8.2f +- %5.2f MPa  %7.1f s  load %.1f  per realization: %.0f factorizations, %.0f evaluations; reruns %d\n",
              label, count, s.exponent.mean, s.exponent.halfWidth, s.coefficient.mean / 1e6, s.coefficient.halfWidth / 1e6,
              t.seconds, t.load, static_cast<double>(s.counters.factorizations) / count,
              static_cast<double>(s.counters.evaluations) / count, reruns);
}

// n', K' of the first `count` realizations of a study.
void printPrefix(const char* label, const GamutStudy& s, std::size_t count) {
  std::vector<double> n, k;
  for (std::size_t r = 0; r < count; ++r) {
    n.push_back(s.runs[r].fit.exponent);
    k.push_back(s.runs[r].fit.coefficient / 1e6);
  }
  const MeanInterval mn = meanInterval(n), mk = meanInterval(k);
  std::printf("%-28s %5zu  n' %.5f +- %.5f  K' %8.2f +- %5.2f MPa\n", label, count, mn.mean, mn.halfWidth, mk.mean, mk.halfWidth);
}

}  // namespace

int main(int argc, char** argv) try {
  std::string material = "both", grid = "both", csvPrefix, png;
  int realizations = 30, bonds = 500, steps = 4, monotonic = 0;
  std::uint64_t seed = 2023;
  bool convergence = false, sensitivity = false, skipTable = false;
  CLI::App app{"gamut_bar: cyclic n', K' of the 002 bar beside 002 Table 1"};
  app.add_option("--material", material, "1, 2 or both")->check(CLI::IsMember({"1", "2", "both"}))->capture_default_str();
  app.add_option("--grid", grid, "uniform, stochastic or both")
      ->check(CLI::IsMember({"uniform", "stochastic", "both"}))
      ->capture_default_str();
  app.add_option("--realizations", realizations, "realizations per study")->check(CLI::Range(2, 100000))->capture_default_str();
  app.add_option("--bonds", bonds, "local bonds")->check(CLI::Range(4, 4000))->capture_default_str();
  app.add_option("--steps", steps, "force steps per half cycle")->check(CLI::Range(1, 1000))->capture_default_str();
  app.add_option("--seed", seed, "seed of the realizations")->capture_default_str();
  app.add_flag("--skip-table", skipTable, "leave out the Table 1 rows");
  app.add_flag("--convergence", convergence, "convergence in realizations and bonds (Material 1, uniform grid)");
  app.add_flag("--sensitivity", sensitivity, "sensitivity to the scatter denominator and Weibull shape");
  app.add_option("--monotonic", monotonic, "realizations of the monotonic ramp per material and grid (0: none)")
      ->check(CLI::Range(0, 100000));
  app.add_option("--csv", csvPrefix, "prefix of the mean monotonic curve CSV files");
  app.add_option("--png", png, "plot of the mean monotonic curves (gnuplot)");
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows appear as they are computed

  std::vector<int> materials;
  if (material != "2") materials.push_back(1);
  if (material != "1") materials.push_back(2);
  std::vector<bool> grids;
  if (grid != "stochastic") grids.push_back(false);
  if (grid != "uniform") grids.push_back(true);
  auto cyclicSpec = [&](int m, bool stochasticGrid, int count, int nBonds) {
    GamutStudySpec spec;
    spec.bar = barSpec(m, stochasticGrid, nBonds, seed);
    spec.realizations = count;
    spec.protocol.stepsPerHalfCycle = steps;
    return spec;
  };

  std::printf("# 002 bar, L = 0.1 m, A = 1e-4 m^2, %d bonds, %d force steps per half cycle, seed %llu, %d threads\n",
              bonds, steps, static_cast<unsigned long long>(seed), omp_get_max_threads());
  for (int m : skipTable ? std::vector<int>{} : materials) {
    const RambergOsgood mat = m == 1 ? gamutMaterial1() : gamutMaterial2();
    const Reference& ref = kTable1[m - 1];
    std::printf("\n## Material %d: 6 amplitudes %.1f .. %.1f MPa\n", m, mat.yieldStress / 1e6, mat.failureStress / 1e6);
    // The deterministic bar: no scatter, uniform grid.
    GamutBarSpec det = barSpec(m, false, bonds, seed);
    det.scatterProperties = false;
    const GamutBar bar(det, 0);
    GamutBarSolver solver(bar);
    const CyclicLoops loops = cyclicLoading(solver, gamutCyclicProtocol(mat, 6, steps), det.area);
    const CyclicFit fit = fitCyclicCurve(loops.stressAmplitude, loops.plasticStrainAmplitude);
    std::printf("%-28s %5d  n' %.5f            K' %8.2f MPa           (002 Table 1: %.5f, %.1f MPa)\n",
                "deterministic", 1, fit.exponent, fit.coefficient / 1e6, ref.deterministicN, ref.deterministicK);
    std::printf("%-28s %5s  n' %.5f            K' %8.2f MPa           (experiment: %s)\n", "Masing baseline 1/n_ro", "-",
                mat.masingExponent(), mat.masingCoefficient() / 1e6, ref.experiment);
    for (bool stochasticGrid : grids) {
      const Timed t = run(cyclicSpec(m, stochasticGrid, realizations, bonds));
      printRow(stochasticGrid ? "stochastic grid" : "uniform grid", t, static_cast<std::size_t>(realizations));
      std::printf("%-28s %5s  n' %.5f            K' %8.2f MPa           largest loop closure %.1e\n", "  002 Table 1", "30",
                  stochasticGrid ? ref.stochasticN : ref.uniformN, stochasticGrid ? ref.stochasticK : ref.uniformK,
                  [&] {
                    double c = 0;
                    for (const auto& r : t.study.runs) c = std::max(c, r.loops.closure);
                    return c;
                  }());
    }
  }

  if (convergence) {
    std::printf("\n## Convergence, Material 1, uniform grid\n");
    const Timed t = run(cyclicSpec(1, false, 300, bonds));
    for (std::size_t count : {30, 100, 300}) printPrefix("realizations", t.study, count);
    std::printf("(300 realizations: %.1f s, load %.1f)\n", t.seconds, t.load);
    for (int b : {125, 250, 500, 1000}) {
      const Timed tb = run(cyclicSpec(1, false, realizations, b));
      printRow(("bonds " + std::to_string(b)).c_str(), tb, static_cast<std::size_t>(realizations));
    }
  }

  if (sensitivity) {
    std::printf("\n## Sensitivity, Material 1, uniform grid (RMS of the relative scatter: sqrt(Gamma(1 + 2/shape)) / denominator)\n");
    for (double denominator : {5.0, 10.0, 20.0, 40.0}) {
      GamutStudySpec spec = cyclicSpec(1, false, realizations, bonds);
      spec.bar.scatter.denominator = denominator;
      printRow(("denominator " + std::to_string(static_cast<int>(denominator))).c_str(), run(spec),
               static_cast<std::size_t>(realizations));
    }
    for (double shape : {1.0, 2.0, 4.0}) {
      GamutStudySpec spec = cyclicSpec(1, false, realizations, bonds);
      spec.bar.scatter.weibullShape = shape;
      printRow(("Weibull shape " + std::to_string(static_cast<int>(shape))).c_str(), run(spec),
               static_cast<std::size_t>(realizations));
    }
  }

  if (monotonic > 0) {
    std::printf("\n## Mean monotonic curve (%d realizations): stress, mean strain, Ramberg-Osgood strain\n", monotonic);
    std::string plot;
    for (int m : materials)
      for (bool stochasticGrid : grids) {
        GamutStudySpec spec = cyclicSpec(m, stochasticGrid, monotonic, bonds);
        spec.cyclic = false;
        spec.monotonic = true;
        const Timed t = run(spec);
        const RambergOsgood mat = spec.bar.material;
        double worst = 0;  // largest |mean strain / RO strain - 1| beyond the yield stress
        for (std::size_t s = 0; s < t.study.meanStress.size(); ++s)
          if (t.study.meanStress[s] > mat.yieldStress)
            worst = std::max(worst, std::abs(t.study.meanStrain[s] / mat.strain(t.study.meanStress[s]) - 1));
        std::printf("material %d %-10s %zu steps, last %.1f MPa at %.4f (RO %.4f), max |strain/RO - 1| above sigma_y %.3f, %.1f s, load %.1f\n",
                    m, stochasticGrid ? "stochastic" : "uniform", t.study.meanStress.size(), t.study.meanStress.back() / 1e6,
                    t.study.meanStrain.back(), mat.strain(t.study.meanStress.back()), worst, t.seconds, t.load);
        for (std::size_t r = 0; r < t.study.runs.size(); ++r)
          if (!t.study.runs[r].curve.stopped.empty())
            std::printf("  realization %zu stopped at %.1f MPa, strain %.4f: %s\n", r, t.study.runs[r].curve.stress.back() / 1e6,
                        t.study.runs[r].curve.strain.back(), t.study.runs[r].curve.stopped.c_str());
        if (!csvPrefix.empty()) {
          const std::string path = csvPrefix + "_m" + std::to_string(m) + (stochasticGrid ? "_stochastic" : "_uniform") + ".csv";
          std::ofstream out(path);
          out << "stress_MPa,mean_strain,ramberg_osgood_strain\n";
          for (std::size_t s = 0; s < t.study.meanStress.size(); ++s)
            out << t.study.meanStress[s] / 1e6 << ',' << t.study.meanStrain[s] << ',' << mat.strain(t.study.meanStress[s]) << '\n';
          plot += (plot.empty() ? "" : ", ") + host::gnuplotQuoted(path) + " using 2:1 with lines lw 2 title " +
                  host::gnuplotQuoted("material " + std::to_string(m) + (stochasticGrid ? ", stochastic grid" : ", uniform grid") + ", mean") +
                  (stochasticGrid ? "" : ", " + host::gnuplotQuoted(path) + " using 3:1 with lines dt 2 lc rgb 'black' title " +
                                             host::gnuplotQuoted("material " + std::to_string(m) + ", Ramberg-Osgood"));
        }
      }
    if (!png.empty() && !plot.empty()) {
      if (!host::gnuplotAvailable()) {
        std::printf("no gnuplot on PATH: no picture\n");
      } else {
        const std::string complaint = host::runGnuplot(
            "set terminal pngcairo size 900,600\nset output " + host::gnuplotQuoted(png) +
            "\nset datafile separator ','\nset key bottom right\nset xlabel 'strain'\nset ylabel 'stress [MPa]'\n"
            "set title 'Mean monotonic curves of the 002 bar against Ramberg-Osgood'\nplot " + plot + "\n");
        std::printf("%s\n", complaint.empty() ? ("plot: " + png).c_str() : complaint.c_str());
      }
    }
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "gamut_bar: " << e.what() << '\n';
  return 1;
}
