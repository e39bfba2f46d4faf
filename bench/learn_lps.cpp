// Learns the LPS model of 003 from the coarse-grained MD data of scripts/md/generate.py: kernel and moduli
// (variable projection + Levenberg-Marquardt, 003 Algorithm 1 (iv)) for every (delta, P) of a grid, the pair
// chosen by the validation residual; solvability (003:(37)) and the explicit stability limit of each kernel.
//   learn_lps [--data data/learning/graphene_md.h5] [--deltas 10,15,20,25] [--orders 1,2,3,4] [--margin 1]
//             [--increments] [--s0-set fracture_train|fracture_test] [--nonnegative-kernel] [--paper-operator]
// then s0 by a 1-D minimization on frames 5-20 of the fracture training sample (003 Algorithm 1 (v)): of the
// equation residual 003:(42), and of the prediction's displacement error (the project's s0).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "learning/coarse_data_file.hpp"
#include "learning/data_sets.hpp"
#include "learning/fracture_residual.hpp"
#include "learning/kernel_fit.hpp"
#include "learning/learned_lps_force_model.hpp"
#include "learning/md_fracture_samples.hpp"
#include "learning/lps_symbol.hpp"
#include "learning/prediction_window_loss.hpp"
#include "solvers/dynamic_problem.hpp"
#include "solvers/stability_limit.hpp"

using namespace peristep::learning;

namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Learn the LPS kernel and moduli of 003 from coarse-grained MD data"};
  std::string path = "data/learning/graphene_md.h5";
  std::vector<double> deltas{10, 15, 20, 25};
  std::vector<int> orders{1, 2, 3, 4};
  std::size_t firstFrame = 5, lastFrame = 20;
  double margin = 1.0;
  std::size_t scanStride = 8;
  bool increments = false, paperOperator = false;
  KernelFitOptions fitOptions;
  std::string s0Set = "fracture_train";
  app.add_option("--data", path, "HDF5 file of learn_coarse_grain");
  app.add_option("--deltas", deltas, "horizons [A]")->delimiter(',');
  app.add_option("--orders", orders, "Bernstein orders P")->delimiter(',');
  app.add_option("--first-frame", firstFrame, "first frame of the s0 step (003: 5)");
  app.add_option("--last-frame", lastFrame, "last frame of the s0 step (003: 20)");
  app.add_option("--scan-stride", scanStride, "print every n-th point of the s0 scan");
  app.add_option("--s0-set", s0Set, "fracture sample of the s0 step (003: fracture_train; fracture_test: IV)");
  app.add_flag("--increments", increments, "s0 step on u - u(frame 0): frame 0 as the unstressed reference state");
  app.add_flag("--paper-operator", paperOperator,
               "s0 step with 003's operator (corrected dilatation, free-surface sums, delta/h = delta / 5 A) instead "
               "of the prediction's");
  app.add_flag("--nonnegative-kernel", fitOptions.nonnegative, "fit with every Bernstein coefficient D_k >= 0 (K >= 0)");
  app.add_option("--margin", margin, "residual points lie this many delta inside the sheet (003: 2)");
  if (const auto code = peristep::bench::parseArguments(app, argc, argv)) return *code;
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const CoarseDataFile file = readCoarseData(path);
    const StaticData train = staticData(file.sets.at("train")), val = staticData(file.sets.at("validation"));
    const double thickness = file.sets.at("train").thickness;
    std::printf("train %zu samples, validation %zu, lattice %zu x %zu (h = %.3f x %.3f A), rho = %.5f amu/A^3\n",
                train.samples.size(), val.samples.size(), train.lattice.nx, train.lattice.ny, train.lattice.hx,
                train.lattice.hy, train.rho);
    std::printf("%6s %2s %8s %18s %18s %9s %9s %4s %9s %5s %6s\n", "delta", "P", "alpha", "lambda [TPa]",
                "mu [TPa]", "res.train", "res.val", "solv", "dt_crit", "iter", "time");
    struct Best {
      double val = INFINITY, delta = 0;
      int P = 0;
      KernelFit fit;
      double dt = 0;
    } best;
    for (const double delta : deltas)
      for (const int P : orders) {
        const auto t1 = std::chrono::steady_clock::now();
        const LatticeStencil st = makeLatticeStencil(train.lattice.hx, train.lattice.hy, delta);
        StaticResidual res(train.lattice, st, P, train.samples, train.weight);
        const KernelFit fit = fitKernel(res, fitOptions);
        StaticResidual resVal(val.lattice, st, P, val.samples, val.weight);
        const double vloss = relativeResidual(resVal, fit.kernel, fit.lambda, fit.mu);
        const Solvability sol = checkSolvability(train.lattice, st, fit.kernel, fit.lambda, fit.mu);
        double dt = NAN;
        if (sol.solvable()) {
          LearnedLpsForceModel model(train.lattice, st, fit.kernel, fit.lambda, fit.mu, thickness);
          peristep::DynamicProblem problem(model, train.rho);
          dt = peristep::estimateStabilityLimit(problem).criticalStep * kTimeUnit;
        }
        std::printf("%6.1f %2d %8.4f %8.4f +- %6.4f %8.4f +- %6.4f %9.2e %9.2e %4s %9.2e %5d %5.1fs\n", delta, P,
                    fit.kernel.alpha, fit.lambda * kTPaPerEvA3, 1.96 * fit.lambdaError * kTPaPerEvA3,
                    fit.mu * kTPaPerEvA3, 1.96 * fit.muError * kTPaPerEvA3, fit.relativeResidual, vloss,
                    sol.solvable() ? "yes" : "no", dt, fit.iterations, seconds(t1));
        std::fflush(stdout);
        if (sol.solvable() && fit.converged && vloss < best.val) best = {vloss, delta, P, fit, dt};
      }
    if (!std::isfinite(best.val)) throw std::runtime_error("no solvable kernel on the grid");
    const KernelFit& f = best.fit;
    std::printf("\nchosen by the validation residual: delta = %.1f A, P = %d\n", best.delta, best.P);
    std::printf("  alpha  = %.4f +- %.4f (95%%)\n", f.kernel.alpha, 1.96 * f.alphaError);
    std::printf("  lambda = %.4f +- %.4f TPa, mu = %.4f +- %.4f TPa, nu = lambda/(lambda+2mu) = %.4f (plane stress)\n",
                f.lambda * kTPaPerEvA3, 1.96 * f.lambdaError * kTPaPerEvA3, f.mu * kTPaPerEvA3,
                1.96 * f.muError * kTPaPerEvA3, f.lambda / (f.lambda + 2 * f.mu));
    for (std::size_t k = 0; k < f.kernel.D.size(); ++k)
      std::printf("  D_%zu = %.5e +- %.5e (int K|z|^2 = 1)\n", k, f.kernel.D[k], 1.96 * f.DError[k]);
    std::printf("  explicit stability limit %.3e s (MD frame interval 4.95e-14 s)\n", best.dt);
    const double t = thickness * 1e-10;
    const auto c = [&](const char* k) { return file.constants.count(k) ? file.constants.at(k) : NAN; };
    std::printf("\nlattice constants of the potential (lattice_constants.lmp): bond %.4f A, C11 %.1f, C12 %.1f, "
                "C66 %.1f N/m\n  -> lambda = C12/t = %.4f TPa, mu = C66/t = %.4f TPa (t = %.2f A)\n",
                c("bond_length_A"), c("C11_N_per_m"), c("C12_N_per_m"), c("C66_N_per_m"), c("C12_N_per_m") / t * 1e-12,
                c("C66_N_per_m") / t * 1e-12, thickness);
    std::printf("003 Sec. 5.1: delta = 20 A, lambda = -0.4796 TPa, mu = 0.7978 TPa\n");
    std::printf("kernel learning took %.1f s\n", seconds(t0));

    // Step 2 (003 Algorithm 1 (v)): s0 from frames first..last of a fracture sample, by 003:(42).
    const auto t2 = std::chrono::steady_clock::now();
    const CoarseDataSet& frac = file.sets.at(s0Set);
    FractureFrames frames = fractureFrames(frac);
    if (increments) subtractFrame0(frames);
    const LearnedModel model{f.kernel, f.lambda, f.mu, train.lattice.hx};
    // The operator the prediction runs (learning/md_fracture_samples.hpp), or 003's.
    const PredictionVariant variant = paperOperator ? kPaperVariant : PredictionVariant{};
    const double fdelta = predictionHorizon(frac.grid, model, variant);
    const DamagedLpsOperator op = predictionOperator(frac.grid, model, variant);
    // The MD slit (x1 = 0, x2 from -50 to -25 A) is broken from the start.
    const FractureResidual fres(frames, op, firstFrame, lastFrame, margin * fdelta, op.slit(0, -60, 0, -25));
    double smax = 0;  // largest finite stretch
    for (const double s : fres.maxStretch(lastFrame))
      if (std::isfinite(s)) smax = std::max(smax, s);
    const CriticalStretchFit s0 = fitCriticalStretch([&](double s) { return fres.loss(s); }, 0.005, 0.4, 80);
    std::printf("\ncritical stretch by the equation residual 003:(42) (frames %zu-%zu, %zu points %.1f delta inside "
                "the sheet): s0 = %.4f "
                "(%d loss evaluations, %.1f s); largest bond stretch in the data by frame %zu: %.3f\n",
                firstFrame, lastFrame, fres.rows(), margin, s0.s0, s0.evaluations, seconds(t2), lastFrame, smax);
    std::printf("  loss / loss(s0 = 0.4):");
    for (std::size_t i = 0; i < s0.scanS0.size(); i += scanStride)
      std::printf(" %.3f:%.3f", s0.scanS0[i], s0.scanLoss[i] / s0.scanLoss.back());
    std::printf("\n003 Sec. 5.1: s0 = 0.11 (0.145 from the MD data directly)\n");

    // The project's s0 step: the prediction's displacement error on the same frames (003:(42) names no s0 on
    // the MD samples, docs/decisions/0016-s0-from-prediction-error.md). It runs the damaged model forward, which
    // is stable only with K >= 0 (docs/decisions/0015-learned-model-nonnegative-kernel.md).
    if (std::any_of(f.kernel.D.begin(), f.kernel.D.end(), [](double d) { return d < 0; })) {
      std::printf("no s0 by the prediction error: the kernel has negative Bernstein coefficients, and with a "
                  "sign-changing kernel the damaged model is unstable (use --nonnegative-kernel)\n");
      return 0;
    }
    const auto t3 = std::chrono::steady_clock::now();
    const auto sample = std::find_if(kMdFractureSamples.begin(), kMdFractureSamples.end(),
                                     [&](const MdFractureSample& m) { return s0Set == m.set; });
    if (sample == kMdFractureSamples.end()) throw std::runtime_error("--s0-set: not a fracture sample: " + s0Set);
    const CriticalStretchFit byPrediction = learnCriticalStretch(frames, *sample, model, firstFrame, lastFrame, 8, variant);
    std::printf("critical stretch by the prediction error (restarted at frame %zu, frames %zu-%zu): s0 = %.4f at "
                "h = 5 A, 95%% interval [%.4f, %.4f] (%d predictions, %.1f s)\n  loss / loss(s0 = 0.5):",
                firstFrame, firstFrame + 1, lastFrame, byPrediction.s0, byPrediction.lower, byPrediction.upper,
                byPrediction.evaluations, seconds(t3));
    for (std::size_t i = 0; i < byPrediction.scanS0.size(); i += std::max<std::size_t>(1, scanStride / 2))
      std::printf(" %.3f:%.3f", byPrediction.scanS0[i], byPrediction.scanLoss[i] / byPrediction.scanLoss.back());
    std::printf("\n");
  } catch (const std::exception& e) {
    std::cerr << "learn_lps: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
