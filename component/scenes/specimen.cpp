#include "scenes/specimen.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "models/poisson_ratio.hpp"

namespace peristep {

namespace {

std::string text(double x) { return numberText(x); }

// Whether the map has material somewhere along a side's edge row or column.
bool materialAlong(const std::vector<double>& E, const GridSpec& g, Side side) {
  for (std::size_t k = 0; k < (side == Side::Left || side == Side::Right ? g.ny : g.nx); ++k) {
    const std::size_t i = side == Side::Left ? 0 : side == Side::Right ? g.nx - 1 : k;
    const std::size_t j = side == Side::Bottom ? 0 : side == Side::Top ? g.ny - 1 : k;
    if (E[j * g.nx + i] > 0) return true;
  }
  return false;
}

}  // namespace

void validate(const SpecimenSpec& s, const GridSpec& g) {
  validate(g);
  const std::size_t n = g.nx * g.ny;
  const bool generated = s.material == SpecimenMaterial::GlassCeramic;
  // A generated material or an exact solution needs no maps; maps that are given are checked all the same.
  if (!(generated || s.exactSolution != ExactSolution::None) || !s.youngsModulus.empty()) {
    const auto length = [&](const std::vector<double>& map, const char* name) {
      require(map.size() == n, std::string(name) + " has " + std::to_string(map.size()) + " values for the " +
                                   std::to_string(g.ny) + " x " + std::to_string(g.nx) + " grid (ny x nx = " +
                                   std::to_string(n) + ")");
    };
    length(s.youngsModulus, "materialYoungsModulus");
    length(s.poissonRatio, "materialPoissonRatio");
    length(s.fractureEnergy, "materialFractureEnergy");
    length(s.density, "materialDensity");
    bool anyMaterial = false;
    for (std::size_t i = 0; i < n; ++i) {
      const std::string at = "[" + std::to_string(i) + "] (x, y index " + std::to_string(i % g.nx) + ", " +
                             std::to_string(i / g.nx) + ")";
      require(std::isfinite(s.youngsModulus[i]) && s.youngsModulus[i] >= 0,
              "materialYoungsModulus" + at + " must be >= 0 (0: Void), got " + text(s.youngsModulus[i]));
      require(std::isfinite(s.fractureEnergy[i]) && s.fractureEnergy[i] > 0,
              "materialFractureEnergy" + at + " must be positive, got " + text(s.fractureEnergy[i]));
      require(std::isfinite(s.density[i]) && s.density[i] > 0,
              "materialDensity" + at + " must be positive, got " + text(s.density[i]));
      require(admissiblePoissonRatio(s.poissonRatio[i]),
              "materialPoissonRatio" + at + " must lie in (-1, 0.5), got " + text(s.poissonRatio[i]));
      anyMaterial = anyMaterial || s.youngsModulus[i] > 0;
    }
    require(anyMaterial, "materialYoungsModulus is 0 (Void) everywhere: the specimen has no material");
  }
  require(!generated || s.model != SpecimenModel::Dynamic,
          "materialField glassCeramic is for the quasi-static models, quasiStatic and elastic (the dynamic model "
          "reads the maps)");
  for (const double g : s.collarGradient) require(std::isfinite(g), "the collar gradient must be finite");
  require(s.model != SpecimenModel::Dynamic || s.collarGradient == std::array<double, 4>{},
          "the collar gradient (collarDuxDx ... collarDuyDy) moves the quasi-static models' grips; the dynamic "
          "model's grips move at gripVx, gripVy: set it to 0");
  require(g.delta() < std::min(g.Lx, g.Ly),
          "the horizon deltaOverH * h = " + text(g.delta()) + " m is not smaller than the plate (Lx = " + text(g.Lx) +
              " m, Ly = " + text(g.Ly) + " m): use a smaller deltaOverH or a finer grid");
  // A pre-crack may reach into the collar (2 delta), e.g. to cut an edge notch's bonds beyond the edge,
  // but its end (x1, y1), where it grows from, lies in the plate.
  const double X = 0.5 * g.Lx, Y = 0.5 * g.Ly, collar = 2 * g.delta();
  for (std::size_t k = 0; k < s.cracks.size(); ++k) {
    const Segment& c = s.cracks[k];
    const auto inside = [&](double x, double y, double margin) {
      return std::abs(x) <= X + margin && std::abs(y) <= Y + margin;
    };
    require(std::isfinite(c.x0) && std::isfinite(c.y0) && std::isfinite(c.x1) && std::isfinite(c.y1) &&
                inside(c.x0, c.y0, collar) && inside(c.x1, c.y1, 0),
            "pre-crack " + std::to_string(k) + " from (" + text(c.x0) + ", " + text(c.y0) + ") to (" + text(c.x1) +
                ", " + text(c.y1) + ") m leaves the plate [" + text(-X) + ", " + text(X) + "] x [" + text(-Y) +
                ", " + text(Y) + "] m (its start may lie in the collar, 2 delta = " + text(collar) + " m wide)");
  }
  const bool dynamic = s.model == SpecimenModel::Dynamic;
  bool anyHeld = !s.boxes.empty();
  for (std::size_t k = 0; k < 4; ++k) {
    const Grip& grip = s.grips[k];
    if (!grip.held) continue;
    anyHeld = true;
    const std::string name = std::string("the ") + kSideNames[k] + " grip";
    require(std::isfinite(grip.ux) && std::isfinite(grip.uy), name + " needs a finite displacement");
    require(std::isfinite(grip.vx) && std::isfinite(grip.vy), name + " needs a finite velocity");
    require(s.youngsModulus.empty() || materialAlong(s.youngsModulus, g, static_cast<Side>(k)),
            name + " holds a side along which materialYoungsModulus is 0 (Void): it would hold nothing");
    require(dynamic || grip.components == HeldComponents::Both,
            name + " holds one component only (heldX, heldY): that is for specimenModel dynamic; the quasi-static "
                   "models hold a collar in both");
  }
  for (std::size_t b = 0; b < s.boxes.size(); ++b) {
    const GripBox& box = s.boxes[b];
    const std::string name = "grip box " + std::to_string(b);
    require(dynamic, name + " is given, but grip boxes hold points of specimenModel dynamic only");
    require(std::isfinite(box.x0) && std::isfinite(box.y0) && std::isfinite(box.x1) && std::isfinite(box.y1) &&
                box.x0 <= box.x1 && box.y0 <= box.y1,
            name + " [" + text(box.x0) + ", " + text(box.x1) + "] x [" + text(box.y0) + ", " + text(box.y1) +
                "] m needs finite corners with x0 <= x1 and y0 <= y1");
    require(std::isfinite(box.vx) && std::isfinite(box.vy), name + " needs a finite velocity");
  }
  require(anyHeld, "every grip is free: hold at least one side, or the specimen floats");
  for (const auto* rate : {&s.bodyForceRateX, &s.bodyForceRateY}) {
    if (rate->empty()) continue;
    require(dynamic, "a body force (bodyForceRateX, bodyForceRateY) is for specimenModel dynamic only");
    require(rate->size() == n, "bodyForceRate has " + std::to_string(rate->size()) + " values for the " +
                                   std::to_string(n) + " points of the grid");
    for (const double r : *rate) require(std::isfinite(r), "bodyForceRate must be finite everywhere");
  }
  if (s.exactSolution != ExactSolution::None) {
    const bool allHeld = std::all_of(s.grips.begin(), s.grips.end(), [](const Grip& g) { return g.held; });
    require(s.model == SpecimenModel::Elastic && allHeld && s.material == SpecimenMaterial::Maps,
            "an exactSolution is the material, body force and collar data of the whole plate: it needs specimenModel "
            "elastic, every side held and materialField map");
  }
}

ImageSource imageSource(const PointCloud& c, std::size_t p) {
  const std::size_t gx = c.nx + 2 * c.layers;
  const auto gi = static_cast<std::ptrdiff_t>(p % gx) - static_cast<std::ptrdiff_t>(c.layers);
  const auto gj = static_cast<std::ptrdiff_t>(p / gx) - static_cast<std::ptrdiff_t>(c.layers);
  const auto nx = static_cast<std::ptrdiff_t>(c.nx), ny = static_cast<std::ptrdiff_t>(c.ny);
  const std::size_t i = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(gi, 0, nx - 1));
  const std::size_t j = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(gj, 0, ny - 1));
  const Side side = gj < 0 ? Side::Bottom : gj >= ny ? Side::Top : gi < 0 ? Side::Left : Side::Right;
  return {j * c.nx + i, side, gi < 0 || gj < 0 || gi >= nx || gj >= ny};
}

PointCloud specimenCloud(const SpecimenSpec& s, const GridSpec& g) {
  GridSpec grid = g;
  grid.collar = true;
  PointCloud c = makeRectangle(grid);
  std::vector<std::size_t> domain;
  for (std::size_t q = 0; q < c.size(); ++q) {
    const ImageSource n = imageSource(c, q);
    const bool voidMap = isVoidInMap(s, n.image);
    const bool inBox = std::any_of(s.boxes.begin(), s.boxes.end(),
                                   [&](const GripBox& b) { return b.contains(c.x[q], c.y[q]); });
    const bool held = s.grips[static_cast<std::size_t>(n.side)].held || inBox;
    if (voidMap || (n.inCollar && !held)) c.region[q] = Region::Void;
    else if (!n.inCollar) domain.push_back(q);
  }
  c.domain = std::move(domain);
  return c;
}

PointCloud imageCloud(const PointCloud& cloud) {
  PointCloud out = cloud;
  out.domain.clear();
  for (std::size_t q = 0; q < out.size(); ++q)
    if (out.image[q] >= 0) out.domain.push_back(q);
  return out;
}

std::vector<double> onImage(const PointCloud& image, const std::vector<double>& field, std::size_t stride,
                            std::size_t offset) {
  std::vector<double> v;
  v.reserve(image.domain.size());
  for (std::size_t q : image.domain) v.push_back(image.isVoid(q) ? 0.0 : field[stride * q + offset]);
  return v;
}

CollarMotion collarMotion(const SpecimenSpec& s, const PointCloud& c) {
  CollarMotion m;
  for (auto& collar : m.collars) collar.assign(c.size(), 0);
  m.unit.assign(2 * c.size(), 0.0);
  const auto& G = s.collarGradient;
  for (std::size_t q = 0; q < c.size(); ++q) {
    if (c.region[q] != Region::Dirichlet) continue;
    const auto k = static_cast<std::size_t>(imageSource(c, q).side);
    m.collars[k][q] = 1;
    m.unit[2 * q] = s.grips[k].ux + G[0] * c.x[q] + G[1] * c.y[q];
    m.unit[2 * q + 1] = s.grips[k].uy + G[2] * c.x[q] + G[3] * c.y[q];
  }
  return m;
}

int gripOf(const SpecimenSpec& s, const PointCloud& c, std::size_t q) {
  if (c.isVoid(q)) return -1;
  for (std::size_t b = 0; b < s.boxes.size(); ++b)
    if (s.boxes[b].contains(c.x[q], c.y[q])) return static_cast<int>(4 + b);
  const ImageSource src = imageSource(c, q);
  const bool held = src.inCollar && s.grips[static_cast<std::size_t>(src.side)].held;
  return held ? static_cast<int>(src.side) : -1;
}

}  // namespace peristep
