// Streamed PCA of glass-ceramic microstructures (000 Sec. 5, (5.4)): wall time, peak memory and retained
// variance of the 20 leading modes for n realizations of the crystal indicator 000:(5.1) on the
// specimen's grid (collar included, as the scene's material arrays), regenerated from seed base + j on
// every pass instead of being stored.
//
//   pca_modes [--h-um 16,8,4] [--n 2000,20000] [--fraction 0.2] [--modes 20] [--oversampling 20]
//             [--power 6] [--check-power 0] [--dense-check 0] [--csv table.csv]
//
// --check-power Q repeats each run with Q subspace iterations and prints its retained variance, the
// largest relative change of the eigenvalues and the sine of the largest angle between the two mode
// subspaces (accuracy of --power). --dense-check 1 (small grids only: the n x M data matrix and the
// M x M covariance are formed) prints the exact sum of the k leading eigenvalues of the sample
// covariance and the share of it that the streamed modes capture.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "core/memory.hpp"
#include "core/timer.hpp"
#include "geometry/point_cloud.hpp"
#include "random/microstructure_pca.hpp"
#include "scenes/glass_ceramic.hpp"
#include "scenes/microstructure.hpp"

using namespace peristep;

namespace {

// The glass-ceramic specimen's cloud at spacing h (800 x 400 um, collar, free side edges).
PointCloud specimenCloud(double hUm) {
  GridSpec grid = GlassCeramicSpec{}.grid;
  grid.nx = static_cast<std::size_t>(std::lround(800.0 / hUm)) + 1;
  grid.ny = static_cast<std::size_t>(std::lround(400.0 / hUm)) + 1;
  PointCloud cloud = makeRectangle(grid);
  cloud.freeSideEdges();
  return cloud;
}

double subspaceSine(const Eigen::MatrixXd& U, const Eigen::MatrixXd& W) {
  const Eigen::MatrixXd R = W - U * (U.transpose() * W);
  return Eigen::JacobiSVD<Eigen::MatrixXd>(R).singularValues()(0);
}

}  // namespace

int main(int argc, char** argv) try {
  std::vector<double> hs{16, 8, 4}, ns{2000, 20000};
  double fraction = 0.2;
  const PcaSpec defaults;
  std::size_t modes = 20, oversampling = defaults.oversampling, power = defaults.powerIterations, checkPower = 0,
              denseCheck = 0;
  std::string csvPath;
  CLI::App app{"pca_modes: streamed PCA of glass-ceramic microstructures"};
  app.add_option("--h-um", hs, "grid spacings [um], comma separated")->delimiter(',')->capture_default_str();
  app.add_option("--n", ns, "numbers of realizations, comma separated")->delimiter(',')->capture_default_str();
  app.add_option("--fraction", fraction, "crystal volume fraction")->capture_default_str();
  app.add_option("--modes", modes, "number of modes k")->capture_default_str();
  app.add_option("--oversampling", oversampling, "oversampling p")->capture_default_str();
  app.add_option("--power", power, "subspace iterations q")->capture_default_str();
  app.add_option("--check-power", checkPower, "repeat each run with this many subspace iterations")->capture_default_str();
  app.add_option("--dense-check", denseCheck, "1: form the covariance and compare (small grids only)")->capture_default_str();
  app.add_option("--csv", csvPath, "write the table as CSV to this file");
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;
  std::ofstream csv;
  if (!csvPath.empty()) {
    csv.open(csvPath);
    csv << "h_um,M,n,modes,passes,generate_s_per_pass,wall_s,peak_MB,retained,lambda1,lambda_k\n";
  }
  std::printf("# streamed PCA, f = %.2f, k = %zu, p = %zu, q = %zu\n", fraction, modes, oversampling, power);
  std::printf("%6s %7s %6s %6s %10s %9s %8s %9s %10s %10s\n", "h um", "M", "n", "passes", "gen s/pass", "wall s",
              "peak MB", "retained", "lambda_1", "lambda_k");
  for (double hUm : hs) {
    const PointCloud cloud = specimenCloud(hUm);
    const RealizationGenerator crystals = [&cloud, fraction](std::size_t j, std::span<double> out) {
      const std::vector<std::uint8_t> R = generateMicrostructure(cloud, fraction, 1 + j);  // seed base 1
      for (std::size_t p = 0; p < R.size(); ++p) out[p] = R[p];
    };
    for (double nd : ns) {
      const auto n = static_cast<std::size_t>(nd);
      // Generation alone (one pass, serial), to separate it from the covariance products.
      Stopwatch gen;
      std::vector<double> buffer(cloud.size());
      const std::size_t probe = std::min<std::size_t>(n, 500);
      for (std::size_t j = 0; j < probe; ++j) crystals(j, buffer);
      const double generatePerPass = gen.seconds() * static_cast<double>(n) / static_cast<double>(probe);

      resetPeakMemory();
      Stopwatch wall;
      const PcaModes pca = streamedPca({cloud.size(), n, modes, oversampling, power, 1}, crystals);
      const double seconds = wall.seconds();
      const double peakMB = static_cast<double>(peakMemoryBytes()) / 1048576.0;
      const auto k = static_cast<Eigen::Index>(pca.size());
      std::printf("%6g %7zu %6zu %6zu %10.2f %9.1f %8.0f %9.4f %10.4g %10.4g\n", hUm, cloud.size(), n, pca.passes,
                  generatePerPass, seconds, peakMB, pca.retainedFraction(), pca.variances[0], pca.variances[k - 1]);
      std::fflush(stdout);
      if (csv)
        csv << hUm << ',' << cloud.size() << ',' << n << ',' << modes << ',' << pca.passes << ',' << generatePerPass
            << ',' << seconds << ',' << peakMB << ',' << pca.retainedFraction() << ',' << pca.variances[0] << ','
            << pca.variances[k - 1] << '\n';
      if (checkPower > 0) {
        const PcaModes ref = streamedPca({cloud.size(), n, modes, oversampling, checkPower, 1}, crystals);
        const double change = ((pca.variances - ref.variances).array() / ref.variances.array()).abs().maxCoeff();
        std::printf("       q = %zu against q = %zu: retained %.4f against %.4f, max relative eigenvalue change "
                    "%.2e, sin(subspace angle) %.2e\n",
                    power, checkPower, pca.retainedFraction(), ref.retainedFraction(), change,
                    subspaceSine(ref.modes, pca.modes));
      }
      if (denseCheck > 0) {
        Eigen::MatrixXd data(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(cloud.size()));
        std::vector<double> row(cloud.size());
        for (std::size_t j = 0; j < n; ++j) {
          crystals(j, row);
          data.row(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::RowVectorXd>(row.data(), data.cols());
        }
        const Eigen::MatrixXd centred = data.rowwise() - data.colwise().mean();
        const Eigen::MatrixXd C = centred.transpose() * centred / static_cast<double>(n - 1);
        const Eigen::VectorXd all =
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(C, Eigen::EigenvaluesOnly).eigenvalues().reverse();
        const auto k = static_cast<Eigen::Index>(pca.size());
        std::printf("       dense: sum of the %td leading eigenvalues %.5g (retained %.4f, lambda_1 %.4g, lambda_k %.4g); "
                    "streamed modes capture %.4f of it\n",
                    k, all.head(k).sum(), all.head(k).sum() / C.trace(), all[0], all[k - 1],
                    pca.variances.sum() / all.head(k).sum());
      }
    }
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "pca_modes: " << e.what() << '\n';
  return 1;
}
