#pragma once
// The importer's specimen (scene Specimen): a plate on the vertex grid of GridSpec (h = Lx/(nx-1), points
// on the edges) with a material per domain point, pre-crack segments at any angle and a grip per side,
// broken quasi-statically by the LPS fracture driver (000 Sec. 3.3) or dynamically by the state-based
// model of 001 with its time integrator.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/option_table.hpp"
#include "geometry/point_cloud.hpp"
#include "geometry/segments.hpp"
#include "scenes/manufactured.hpp"

namespace peristep {

enum class SpecimenModel { QuasiStatic, Dynamic, Elastic };

// Every model of the specimen, its name and description (the FMI enumeration PeriStep.SpecimenModel).
inline constexpr std::array<Option<SpecimenModel>, 3> kSpecimenModelOptions{{
    {SpecimenModel::QuasiStatic, "quasiStatic",
     "LPS with brittle bonds (000 Sec. 3.3): every step moves the held grips by loadFactor * (gripUx, gripUy) "
     "and breaks bonds until equilibrium at that load"},
    {SpecimenModel::Dynamic, "dynamic",
     "State-based model of 001 (bulkModulus, poissonRatio, criticalEnergyReleaseRate) integrated in time by "
     "timeIntegrator: the held grips move at loadFactor * (gripVx, gripVy); materialYoungsModulus marks Void "
     "and scales the stiffness point by point (and with it the bonds' fracture energy), materialDensity gives "
     "the mass"},
    {SpecimenModel::Elastic, "elastic",
     "LPS without fracture (000 Sec. 3.1): one factorization, every step one solve with the held grips at "
     "loadFactor times their displacement; Void and pre-cracks shape the plate, nothing breaks "
     "(materialFractureEnergy is not read)"},
}};

enum class Side { Left = 0, Right = 1, Bottom = 2, Top = 3 };
inline constexpr std::array<const char*, 4> kSideNames{"left", "right", "bottom", "top"};

// Where the material of the points comes from: the maps; the maps' Young's modulus times a Karhunen-Loeve
// factor of mean 1 from the scene's xi, covariance, correlation length, standard deviation and transform
// (scenes/kl_material.hpp), Void staying Void; or the glass-ceramic of 000 Sec. 5 on every point of the
// cloud, collar included (scenes/glass_ceramic_material.hpp: the microstructure of `seed` at
// crystalFraction, or its PCA field with pcaRealizations > 0), where a map given marks Void only.
enum class SpecimenMaterial { Maps, KlField, GlassCeramic };

// Which input moves the held grips: loadFactor (the specimen's own), or loadDisplacement [m] (the
// glassCeramic scene's U_D; its grips' displacements are then per metre of U_D).
enum class SpecimenLoad { LoadFactor, LoadDisplacement };

// Which displacement components a grip prescribes: both, or (dynamic model) one, the other left free.
enum class HeldComponents { Both, X, Y };

// A held side's collar moves rigidly: by load * (ux, uy) in the quasi-static models (plus the specimen's
// collar gradient), at the velocity load * (vx, vy) in the dynamic one. A free side has no collar
// (traction-free).
struct Grip {
  bool held = false;
  double ux = 0, uy = 0;  // [m] at load 1
  double vx = 0, vy = 0;  // [m/s] at load 1
  HeldComponents components = HeldComponents::Both;
};

// Dynamic model: the points of the specimen's cloud inside the closed rectangle [x0, x1] x [y0, y1] (domain
// points as well as collar points, which then exist beside a free side too) move at load * (vx, vy) in the
// held components; a point in several boxes goes with the first. Supports inside a beam, a collar split in
// two, a strip along part of a side.
struct GripBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [m]
  double vx = 0, vy = 0;                  // [m/s] at load 1
  HeldComponents components = HeldComponents::Both;
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

struct SpecimenSpec {
  SpecimenModel model = SpecimenModel::QuasiStatic;
  // Per domain point, image order [ny][nx]. youngsModulus 0 marks Void: no material (a hole, a cut-out).
  std::vector<double> youngsModulus, poissonRatio, fractureEnergy;  // [Pa], -, [J/m^2]
  std::vector<double> density;  // [kg/m^3], read by the dynamic model
  std::vector<Segment> cracks;  // pre-cracks (of positive length): bonds crossing one are broken from the start
  std::array<Grip, 4> grips{};  // by Side
  std::vector<GripBox> boxes;   // dynamic model
  // Dynamic model: a body force growing linearly in time, b = load * t * rate, per domain point [N/(m^3 s)]
  // (empty: none).
  std::vector<double> bodyForceRateX, bodyForceRateY;
  // Quasi-static models: every held collar point (x, y) also moves by load * G (x, y), G = {du_x/dx,
  // du_x/dy, du_y/dx, du_y/dy}: a homogeneous strain or rotation imposed on the whole boundary.
  std::array<double, 4> collarGradient{};
  SpecimenMaterial material = SpecimenMaterial::Maps;
  SpecimenLoad load = SpecimenLoad::LoadFactor;
  // Elastic model, every side held: the material, body force and collar displacement (times the load) of a
  // manufactured solution instead of the maps and grips.
  ExactSolution exactSolution = ExactSolution::None;
};

// Whether the map marks point `image` as Void (a glass-ceramic specimen may come without maps).
inline bool isVoidInMap(const SpecimenSpec& s, std::size_t image) {
  return !s.youngsModulus.empty() && s.youngsModulus[image] == 0;
}

// Throws InvalidInput naming the first inconsistency: a map of the wrong length (a glass-ceramic specimen
// may have none), a negative or non-finite modulus, a fracture energy or density <= 0, nu outside (-1, 0.5),
// a segment whose end leaves the plate or whose start lies beyond the collar, a held grip along a side where
// the map is Void, a horizon larger than the plate, no held grip, a generated material with the dynamic
// model, a non-finite collar gradient or one given to the dynamic model, an exact solution on
// another model than elastic or with a free side or a generated material, a grip of one component, a grip
// box or a body force given to a quasi-static model, a box that holds no material point.
void validate(const SpecimenSpec& s, const GridSpec& grid);

// Where a point of the specimen's cloud (collar included) takes its material from: the nearest image
// point; and for a collar point, the side it sits beside (corners go with bottom and top).
struct ImageSource {
  std::size_t image;
  Side side;
  bool inCollar;
};
ImageSource imageSource(const PointCloud& cloud, std::size_t p);

// The specimen's cloud: the vertex grid with a collar 2 delta thick on every side (000 Sec. 2.1), of which
// the points beside a free side (unless a grip box holds them) or beside Void, and the map's Void points,
// are Void. The domain lists the material points in image order.
PointCloud specimenCloud(const SpecimenSpec& s, const GridSpec& grid);

// The cloud a specimen's outputs are written on: `cloud` with every image point, material or Void, as its
// domain (image order); and a per-point field (`stride` values per point, component `offset`) on its
// domain, 0 on Void.
PointCloud imageCloud(const PointCloud& cloud);
std::vector<double> onImage(const PointCloud& image, const std::vector<double>& field, std::size_t stride,
                            std::size_t offset);

// Where the held collars are and how they move at load 1: per side, 1 on that grip's collar points; per
// point, (u_x, u_y) = grip displacement + collar gradient times (x, y) on the collars, 0 elsewhere.
struct CollarMotion {
  std::array<std::vector<std::uint8_t>, 4> collars;
  std::vector<double> unit;
};
CollarMotion collarMotion(const SpecimenSpec& s, const PointCloud& cloud);

// The grip that holds point q of the specimen's cloud: index k < 4 the side k's collar, 4 + b the grip box b;
// -1 for none (a free point, or a Void one).
int gripOf(const SpecimenSpec& s, const PointCloud& cloud, std::size_t q);

}  // namespace peristep
