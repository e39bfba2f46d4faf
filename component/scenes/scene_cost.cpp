#include "scenes/scene_cost.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "geometry/point_cloud.hpp"
#include "scenes/microstructure.hpp"

namespace peristep {
namespace {

// Rates and sizes the models below are calibrated with (2 threads, Release build).
constexpr double kFlopsPerSecond = 4e9;       // UMFPACK at 201k unknowns: 1.1e11 flop in 26 s
constexpr double kBytesPerFactorEntry = 40;   // UMFPACK working memory per estimated factor entry
constexpr double kBytesPerBond = 40;          // neighbour index, weight, bond state
constexpr double kBytesPerMatrixEntry = 48;   // assembly pieces and the CSR copies of A and B
constexpr double kFlopsPerBond = 200;         // neighbour search, weights, assembly per bond
constexpr double kFlopsPerCrystalCheck = 25;  // one point or cell tested against one ellipse

// Points of the grid with its collar (geometry/point_cloud.hpp).
double collaredPoints(const GridSpec& g) {
  const double layers = static_cast<double>(collarLayers(g.deltaOverH));
  return (static_cast<double>(g.nx) + 2 * layers) * (static_cast<double>(g.ny) + 2 * layers);
}

struct Part {
  double bytes = 0, flops = 0;
  std::string what;
};

// The quasi-static LPS set-up on the collared grid: bonds, assembly and one sparse LU factorization.
// Unknowns: u at the domain points, theta at every point within a horizon of the domain. The
// factorization follows nested dissection on a 2D grid, whose top separator is a band 2 delta wide
// across the domain (3 unknowns per point): about 1.1 s^3 flops and 6 s^2 factor entries (66k
// unknowns: 21 GFlop measured, 18 estimated; 201k: 26 s measured, 27 estimated). Where the separator
// holds half the unknowns or more, dissection gains nothing and the factors are dense (deltaOverH = 20
// on 33 x 33: 73 s measured, 70 estimated).
Part lpsSetUp(const GridSpec& g) {
  const double deltaOverH = g.deltaOverH, nx = static_cast<double>(g.nx), ny = static_cast<double>(g.ny);
  const double inner = std::ceil(deltaOverH - 1e-9);
  const double points = collaredPoints(g), domain = nx * ny;
  const double neighbours = std::numbers::pi * deltaOverH * deltaOverH;
  const double unknowns = 2 * domain + (nx + 2 * inner) * (ny + 2 * inner);
  const double entries = 8 * neighbours * domain;
  const double separator = 3 * std::sqrt(domain) * 2 * deltaOverH;
  const bool dense = 2 * separator >= unknowns;
  const double factorFlops = dense ? 2.0 / 3.0 * std::pow(unknowns, 3) : 1.1 * std::pow(separator, 3);
  const double factorEntries = dense ? unknowns * unknowns : 6 * separator * separator;
  Part p;
  p.bytes = kBytesPerBond * points * neighbours + kBytesPerMatrixEntry * entries + kBytesPerFactorEntry * factorEntries;
  p.flops = kFlopsPerBond * points * neighbours + factorFlops;
  p.what = "the factorization of about " + numberText(unknowns, 2) + " unknowns (" + numberText(factorFlops, 2) +
           " flop, " + numberText(kBytesPerFactorEntry * factorEntries, 2) + " bytes)";
  return p;
}

// Crystals placed until the fraction f is reached (000 Sec. 5): a Boolean model covers 1 - exp(-N a/A)
// of the plate with N ellipses of area a, so N = -ln(1 - f) A / a; each ellipse tests the placement
// raster's cells and then the grid points within its semi-major axis.
Part microstructure(const SceneParameters& p, double realizations) {
  const EllipseShape e;
  const double f = std::min(p.crystalFraction, 0.999);
  const double cell = e.semiMinor / kCoverRasterPerMinorAxis;
  const double checks = std::pow(2 * e.semiMajor / cell + 1, 2) + std::pow(2 * e.semiMajor / p.grid.h() + 3, 2);
  const double crystals = -std::log1p(-f) * p.grid.Lx * p.grid.Ly / (std::numbers::pi * e.semiMajor * e.semiMinor);
  Part m;
  m.flops = realizations * crystals * checks * kFlopsPerCrystalCheck;
  m.what = "placing about " + numberText(crystals, 2) + " crystals of 12 x 7.5 um on the " + numberText(p.grid.Lx, 2) +
           " x " + numberText(p.grid.Ly, 2) + " m plate" +
           (realizations > 1 ? " in each of " + numberText(realizations, 2) + " realizations" : "");
  return m;
}

// The streamed PCA (random/microstructure_pca.hpp): q + 2 passes over n realizations, two block
// products of M x (k + p) per realization and pass, at about a third of the LU's flop rate.
Part pca(const SceneParameters& p) {
  const double M = collaredPoints(p.grid);
  const double n = static_cast<double>(p.pcaRealizations), l = static_cast<double>(p.xi.size()) + 20, passes = 8;
  Part m = microstructure(p, n * passes);
  m.flops += 3 * passes * n * 2 * M * l;
  m.bytes = 8 * M * (4 * l + 64);
  m.what = "the PCA of " + numberText(n, 2) + " realizations (" + m.what + ")";
  return m;
}

// The KL modes on every point (random/kl_field.hpp): dense ~9 N^3 up to 1200 points, else 6 passes of
// N^2 kernel evaluations (~20 flop) times the block of k + 20 columns.
Part klField(const SceneParameters& p) {
  const double N = collaredPoints(p.grid);
  const double l = static_cast<double>(p.xi.size()) + 20;
  Part m;
  m.flops = N <= 1200 ? 9 * N * N * N : 6 * N * N * (20 + 2 * l);
  m.bytes = N <= 1200 ? 24 * N * N : 8 * N * (4 * l + 128);
  m.what = "the KL modes on " + numberText(N, 2) + " points";
  return m;
}

// The dynamic scenes: the specimen's lattice with its collars (2 delta, Void where nothing holds them) and
// at most as many state-based bonds (index, two directions, two weights) as if every point had material;
// no factorization.
Part dynamicSetUp(const GridSpec& g) {
  const auto collar = static_cast<double>(collarLayers(g.deltaOverH));
  const double points = (static_cast<double>(g.nx) + 2 * collar) * (static_cast<double>(g.ny) + 2 * collar);
  const double bonds = points * std::numbers::pi * g.deltaOverH * g.deltaOverH;
  Part m;
  m.bytes = 48 * bonds;
  m.flops = 100 * bonds;
  m.what = "the " + numberText(bonds, 2) + " bonds of the lattice";
  return m;
}

// The 1D bar of 002: its per-point table of partners (weight and critical strain on three images of the
// bar) and the solver's dense matrices (linear part, elastic and current tangent, single-precision factor),
// with one dense Cholesky factorization at set-up; and the (zero) image outputs, ten arrays of nx * ny.
Part gamutBar(const SceneParameters& p) {
  const double n = static_cast<double>(p.gamutBar.bonds), points = n + 1;
  Part m;
  m.bytes = 48 * points * points + 28 * n * n + 80 * static_cast<double>(p.grid.nx) * static_cast<double>(p.grid.ny);
  m.flops = n * n * n / 3 + 200 * points * points;
  m.what = "the dense tangent of " + numberText(n, 2) + " bonds";
  return m;
}

// 003's MD fracture samples (2.5 MB of frames, read once per process) and the learned operator's stencil on
// at most 31 x 31 points: small and fixed.
Part learnedFracture() {
  Part m;
  m.bytes = 4e6;
  m.flops = 1e7;
  m.what = "the MD frames of 003's fracture samples";
  return m;
}

}  // namespace

CostEstimate estimateSetUp(const SceneParameters& p) {
  std::vector<Part> parts;
  if (isDynamic(p)) {
    parts.push_back(dynamicSetUp(p.grid));
  } else if (p.scene == SceneId::GamutBar) {
    parts.push_back(gamutBar(p));
  } else if (p.scene == SceneId::LearnedFracture) {
    parts.push_back(learnedFracture());
  } else {
    parts.push_back(lpsSetUp(p.grid));
    if (usesGlassCeramic(p))
      parts.push_back(p.pcaRealizations > 0 ? pca(p) : microstructure(p, 1));
    if (usesKlField(p)) parts.push_back(klField(p));
  }
  CostEstimate e;
  const Part *memory = &parts.front(), *time = &parts.front();
  for (const Part& part : parts) {
    e.bytes += part.bytes;
    e.seconds += part.flops / kFlopsPerSecond;
    if (part.bytes > memory->bytes) memory = &part;
    if (part.flops > time->flops) time = &part;
  }
  e.mostMemory = memory->what;
  e.mostTime = time->what;
  return e;
}

void checkSetUpLimits(const SceneParameters& p) {
  const WorkLimits& l = p.limits;
  if (l.memoryBytes <= 0 && l.setUpSeconds <= 0) return;
  const CostEstimate e = estimateSetUp(p);
  const std::string change =
      p.scene == SceneId::GamutBar
          ? std::string("use fewer gamutBonds (and nx = ny = 2: the bar has no image)")
          : "use a coarser grid (nx, ny), a smaller deltaOverH" +
                std::string(usesGlassCeramic(p) ? ", a smaller plate or fewer pcaRealizations" : "");
  if (l.memoryBytes > 0 && e.bytes > l.memoryBytes)
    throw InvalidInput("the scene set-up would need about " + numberText(e.bytes, 2) + " bytes of memory (mostly " +
                       e.mostMemory + ") but memoryBudget = " + numberText(l.memoryBytes, 2) + " bytes; " + change +
                       ", or raise memoryBudget");
  if (l.setUpSeconds > 0 && e.seconds > l.setUpSeconds)
    throw InvalidInput("the scene set-up would take about " + numberText(e.seconds, 2) + " s (mostly " + e.mostTime +
                       ") but setUpTimeLimit = " + numberText(l.setUpSeconds, 2) + " s; " + change +
                       ", or raise setUpTimeLimit");
}

}  // namespace peristep
