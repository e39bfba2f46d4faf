#pragma once
// Point clouds on a rectangular domain with a Dirichlet collar (000 Sec. 2.1, Sec. 3.1).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace peristep {

// A rectangle [-Lx/2, Lx/2] x [-Ly/2, Ly/2] sampled with nx x ny points on grid vertices
// (spacing h = Lx/(nx-1) = Ly/(ny-1)), surrounded by a collar of at least 2*delta.
struct GridSpec {
  std::size_t nx = 0, ny = 0;
  double Lx = 1.0, Ly = 1.0;
  double deltaOverH = 3.0;
  double jitter = 0.0;       // random displacement of every point, as a fraction of h (quasi-uniform cloud)
  std::uint64_t seed = 1;    // seed of the jitter
  bool collar = true;        // false: the domain alone (free boundaries on all sides)

  double h() const { return Lx / static_cast<double>(nx - 1); }
  double delta() const { return deltaOverH * h(); }
  // Same cloud: the seed matters only for a jittered one.
  bool sameCloud(const GridSpec& o) const {
    return nx == o.nx && ny == o.ny && Lx == o.Lx && Ly == o.Ly && deltaOverH == o.deltaOverH &&
           jitter == o.jitter && collar == o.collar && (jitter == 0.0 || seed == o.seed);
  }
};

// The ranges of deltaOverH and jitter, for every grid, and the only definition of them (the FMI variables
// take their min and max from here): 1 <= delta/h <= 20 (the collar is 2 delta wide: an unbounded horizon
// would overflow the point count); 0 <= jitter < 0.5 (points stay in their own cells).
inline constexpr double kMinDeltaOverH = 1.0, kMaxDeltaOverH = 20.0;
inline constexpr double kMaxJitter = 0.5;
inline constexpr std::size_t kMinPointsPerSide = 2;  // nx and ny

// Throws InvalidInput with a precise message when the spec cannot describe a valid cloud: the one check of
// the grid's sizes, spacing, horizon and jitter for every scene.
void validate(const GridSpec& spec);
// The one check of the horizon's range: throws InvalidInput outside [kMinDeltaOverH, kMaxDeltaOverH].
void validateHorizon(double deltaOverH);

// Where a point sits: in the domain (unknown u), in the Dirichlet collar (prescribed u), or in the
// collar beyond a free edge (no material: its bonds are broken from the start, 000 Sec. 3.3).
enum class Region : std::uint8_t { Domain, Dirichlet, Void };

// Points stored as structure of arrays; the full grid, collar included, is numbered row-major.
struct PointCloud {
  double h = 0.0, delta = 0.0;
  std::size_t nx = 0, ny = 0;        // domain points per side
  std::size_t layers = 0;            // collar layers on each side
  std::vector<double> x, y;
  std::vector<std::int64_t> image;   // per point: index into the [ny][nx] domain image, -1 in the collar
  std::vector<std::size_t> domain;   // point ids of the domain points, in image order
  std::vector<Region> region;

  std::size_t size() const { return x.size(); }
  bool inDomain(std::size_t p) const { return region[p] == Region::Domain; }
  bool isVoid(std::size_t p) const { return region[p] == Region::Void; }
  // Points with material: domain and held collar (Void ones are placeholders of the grid).
  std::size_t materialPoints() const {
    return static_cast<std::size_t>(std::count_if(region.begin(), region.end(), [](Region r) { return r != Region::Void; }));
  }

  // Collar points beside the left/right edges (within the domain's y range) become Void: those edges
  // are free. The corner blocks stay with the top and bottom collars.
  void freeSideEdges();
};

// 000 Sec. 2.1: u is prescribed on a collar of thickness 2 delta, this many layers on each side.
inline std::size_t collarLayers(double deltaOverH) {
  return static_cast<std::size_t>(std::ceil(2.0 * deltaOverH - 1e-9));
}

PointCloud makeRectangle(const GridSpec& spec);

}  // namespace peristep
