#include "scenes/plexiglass_crack.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace peristep {

SpecimenSpec plexiglassCrackPreset(const GridSpec& g, const StateBasedInput& material, double pullVelocity) {
  const double h = g.h(), eps = g.delta(), X = 0.5 * g.Lx, Y = 0.5 * g.Ly;
  const double L = g.Lx + h, bottomFace = -Y - 0.5 * h;
  SpecimenSpec s;
  s.model = SpecimenModel::Dynamic;
  assignUniformMaterial(s, g.nx * g.ny, material);
  // Boxes reach half a spacing past the rows they hold, so no point sits on an edge; the middle column
  // (odd nx) lies in both bottom boxes and goes with the first, the left one.
  const double top0 = Y + 0.5 * h, top1 = Y + eps + 0.5 * h, bottom0 = -Y - eps - 0.5 * h, bottom1 = -Y - 0.5 * h;
  const double left = -X - 0.5 * h, right = X + 0.5 * h, middle = 0.25 * h;
  s.boxes = {{.x0 = left, .y0 = top0, .x1 = right, .y1 = top1, .vx = 0, .components = HeldComponents::X},
             {.x0 = left, .y0 = bottom0, .x1 = middle, .y1 = bottom1, .vx = -pullVelocity, .components = HeldComponents::X},
             {.x0 = -middle, .y0 = bottom0, .x1 = right, .y1 = bottom1, .vx = pullVelocity, .components = HeldComponents::X}};
  s.cracks = {Segment{0.0, bottom0, 0.0, bottomFace + L / 5}};
  return s;
}

GridSpec plexiglassCrackGrid(const PlexiglassCrackSpec& spec) {
  validateHorizon(spec.meshRatio);
  require(spec.horizon > 0 && spec.side > 0, "Plexiglass crack: a positive horizon and side are required");
  const double h = spec.horizon / spec.meshRatio, cells = spec.side / h;
  require(std::abs(cells - std::round(cells)) < 1e-6,
          "Plexiglass crack: h = eps/(eps/h) = " + std::to_string(h) + " m must divide the side");
  GridSpec g;
  g.nx = g.ny = static_cast<std::size_t>(std::llround(cells));
  g.Lx = g.Ly = spec.side - h;
  g.deltaOverH = spec.meshRatio;
  return g;
}

DynamicScene makePlexiglassCrack(const PlexiglassCrackSpec& spec) {
  const GridSpec g = plexiglassCrackGrid(spec);
  return makeDynamicPreset(g, spec.material, plexiglassCrackPreset(g, spec.material, spec.pullVelocity), spec.timeStep,
                           spec.endTime);
}

}  // namespace peristep
