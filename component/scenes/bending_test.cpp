#include "scenes/bending_test.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace peristep {

SpecimenSpec bendingPreset(const GridSpec& g, int cracks, const StateBasedInput& material, const BendingLayout& l) {
  require(cracks == 1 || cracks == 2, "bending test: 1 or 2 pre-cracks (got " + std::to_string(cracks) + ")");
  const double h = g.h(), eps = g.delta();
  const double length = g.Lx + h, depth = g.Ly + h, sx = length / kBeamLength, sy = depth / kBeamDepth;
  const double leftFace = -0.5 * length, bottomFace = -0.5 * depth;
  require(l.crackLength * sy < depth && l.loadDepth * sy < depth,
          "bending test: the pre-cracks and the load band must lie inside the beam");
  SpecimenSpec s;
  s.model = SpecimenModel::Dynamic;
  const std::size_t n = g.nx * g.ny;
  assignUniformMaterial(s, n, material);
  for (const double x : cracks == 1 ? std::vector<double>{0.0} : std::vector<double>{-l.crackOffset * sx, l.crackOffset * sx})
    s.cracks.push_back(Segment{x, bottomFace - 0.5 * h, x, bottomFace + l.crackLength * sy});
  // Supports: the nodes closer than eps to the bottom face (the box stops just short of eps).
  for (const double centre : {leftFace + l.supportCentre * sx, -leftFace - l.supportCentre * sx})
    s.boxes.push_back({.x0 = centre - l.supportHalfWidth * sx, .y0 = bottomFace, .x1 = centre + l.supportHalfWidth * sx,
                       .y1 = bottomFace + eps * (1 - 1e-9), .components = HeldComponents::Y});
  // Rows of nodes carrying the load: those whose cells lie within the band, at least the top row.
  const double d = l.loadDepth * sy, w = l.loadHalfWidth * sx;
  const auto rows = static_cast<std::size_t>(std::max(1.0, std::floor(d / h + 1e-9)));
  const double bandScale = d / (static_cast<double>(rows) * h);
  s.bodyForceRateY.assign(n, 0.0);
  for (std::size_t j = g.ny - rows; j < g.ny; ++j)
    for (std::size_t i = 0; i < g.nx; ++i) {
      const double dm = std::abs(-0.5 * g.Lx + static_cast<double>(i) * h);
      if (dm <= w) s.bodyForceRateY[j * g.nx + i] = bandScale * l.loadRate * (1.0 - dm / w);
    }
  return s;
}

DynamicScene makeBendingTest(const BendingSpec& spec) {
  validateHorizon(spec.meshRatio);
  require(spec.horizon > 0 && spec.length > 0 && spec.depth > 0, "bending test: positive sizes are required");
  const double h = spec.horizon / spec.meshRatio, cx = spec.length / h, cy = spec.depth / h;
  require(std::abs(cx - std::round(cx)) < 1e-6 && std::abs(cy - std::round(cy)) < 1e-6,
          "bending test: h = " + std::to_string(h) + " m must divide the beam's length and depth");
  GridSpec g;
  g.nx = static_cast<std::size_t>(std::llround(cx));
  g.ny = static_cast<std::size_t>(std::llround(cy));
  g.Lx = spec.length - h;
  g.Ly = spec.depth - h;
  g.deltaOverH = spec.meshRatio;
  return makeDynamicPreset(g, spec.material, bendingPreset(g, spec.cracks, spec.material, spec.layout), spec.timeStep,
                           spec.endTime);
}

}  // namespace peristep
