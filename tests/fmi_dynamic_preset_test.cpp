// The dynamic scenes of 001 Sec. 6 are presets of the dynamic specimen: through the C ABI, each equals the
// specimen whose variables spell out 001's set-up (grip boxes held in one component, pre-cracks, the
// bending load as a body-force map), bit for bit. And the grip boxes and body force are refused where they
// do not apply.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fmi_abi_support.hpp"
#include "fmi_refusal.hpp"
#include "fmi_scene_setups.hpp"

namespace {

constexpr double kE0 = 3 * 25e9 * (1 - 2 * 0.25);  // 3 K (1 - 2 nu) of 001 Table 1

struct Box {
  double x0, y0, x1, y1;
  std::int64_t hold;
  double vx, vy;
};

struct Segment {
  double x0, y0, x1, y1;
};

// A dynamic specimen of one material on an nx x ny grid spanning Lx x Ly, every side free, held by boxes.
void setUpSpecimen(Session& s, std::uint64_t nx, std::uint64_t ny, double Lx, double Ly, double deltaOverH,
                   const std::vector<Box>& boxes, const std::vector<Segment>& cracks) {
  REQUIRE(s.configureStructural({PERISTEP_VR_NX, PERISTEP_VR_NY, PERISTEP_VR_NCRACKS, PERISTEP_VR_NGRIP_BOXES},
                                {nx, ny, cracks.size(), boxes.size()}) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_SPECIMEN) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_DYNAMIC) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {Lx}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {Ly}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {deltaOverH}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.25}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, std::vector<double>(nx * ny, kE0)) == fmi3OK);
  for (const fmi3ValueReference grip : {PERISTEP_VR_GRIP_LEFT, PERISTEP_VR_GRIP_RIGHT, PERISTEP_VR_GRIP_BOTTOM,
                                        PERISTEP_VR_GRIP_TOP})
    REQUIRE(s.setInt64(grip, PERISTEP_GRIP_FREE) == fmi3OK);
  const auto column = [](const auto& rows, auto member) {
    std::vector<double> c;
    for (const auto& r : rows) c.push_back(r.*member);
    return c;
  };
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_X0, column(cracks, &Segment::x0)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_Y0, column(cracks, &Segment::y0)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_X1, column(cracks, &Segment::x1)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_Y1, column(cracks, &Segment::y1)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_X0, column(boxes, &Box::x0)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_Y0, column(boxes, &Box::y0)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_X1, column(boxes, &Box::x1)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_Y1, column(boxes, &Box::y1)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_VX, column(boxes, &Box::vx)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_VY, column(boxes, &Box::vy)) == fmi3OK);
  std::vector<fmi3Int64> hold;
  for (const Box& b : boxes) hold.push_back(b.hold);
  const fmi3ValueReference holdVr = PERISTEP_VR_GRIP_BOX_HOLD;
  REQUIRE(s.fmu.fmi3SetInt64(s.instance, &holdVr, 1, hold.data(), hold.size()) == fmi3OK);
}

// Every output a dynamic scene computes, after `steps` communication steps of `step` seconds.
std::vector<std::vector<double>> run(Session& s, std::size_t points, int steps, double step) {
  REQUIRE(s.initialize(0, steps * step) == fmi3OK);
  for (int k = 0; k < steps; ++k) REQUIRE(s.step(k * step, step) == fmi3OK);
  std::vector<std::vector<double>> out;
  for (const fmi3ValueReference vr : {PERISTEP_VR_UX, PERISTEP_VR_UY, PERISTEP_VR_DAMAGE, PERISTEP_VR_YOUNGS_MODULUS})
    out.push_back(s.getFloat64(vr, points));
  for (const fmi3ValueReference vr : {PERISTEP_VR_KINETIC_ENERGY, PERISTEP_VR_STRAIN_ENERGY, PERISTEP_VR_EXTERNAL_WORK,
                                      PERISTEP_VR_FRACTURE_ENERGY, PERISTEP_VR_CRACK_LENGTH})
    out.push_back(s.getFloat64(vr));
  CHECK(s.log.errors() == 0);
  return out;
}

}  // namespace

TEST_CASE("the Plexiglass crack is the dynamic specimen of its strips and pre-crack", "[abi][dynamics][preset]") {
  // 25 x 25 points, h = 4 mm (the cells span 0.1 m), eps = 2 h: the collars are 2 rows of cells.
  constexpr std::uint64_t n = 25;
  constexpr double h = 0.004, X = 0.048, eps = 2 * h;
  Session preset, spelled;
  setUpCoarseScene(preset, PERISTEP_SCENE_PLEXIGLASS_CRACK);
  // Top strip held in x; the bottom one split at the crack line, its halves pulled apart at 1 m/s (the
  // middle column with the left half); the crack from below the strip to 0.02 m above the bottom face.
  const double top0 = X + h / 2, top1 = X + eps + h / 2, bottom0 = -X - eps - h / 2, bottom1 = -X - h / 2;
  setUpSpecimen(spelled, n, n, 2 * X, 2 * X, 2.0,
                {{-X - h / 2, top0, X + h / 2, top1, PERISTEP_GRIP_HELD_X, 0.0, 0.0},
                 {-X - h / 2, bottom0, h / 4, bottom1, PERISTEP_GRIP_HELD_X, -1.0, 0.0},
                 {-h / 4, bottom0, X + h / 2, bottom1, PERISTEP_GRIP_HELD_X, 1.0, 0.0}},
                {{0.0, bottom0, 0.0, -X - h / 2 + 0.02}});
  REQUIRE(spelled.setFloat64(PERISTEP_VR_INTERNAL_TIME_STEP, {0.004e-6}) == fmi3OK);  // 001's step
  const auto a = run(preset, n * n, 3, 2e-6), b = run(spelled, n * n, 3, 2e-6);
  CHECK(a == b);
  CHECK(a[6][0] > 0);  // the strips have done work
  // The strips pull the specimen's bottom apart: the left box's force on it points to -x, the right's to +x.
  const auto rx = spelled.getFloat64(PERISTEP_VR_GRIP_BOX_REACTION_X, 3);
  CHECK(rx[1] < 0);
  CHECK(rx[2] > 0);
  CHECK(spelled.getFloat64(PERISTEP_VR_GRIP_BOX_REACTION_Y, 3) == std::vector<double>{0.0, 0.0, 0.0});  // y free
}

TEST_CASE("the bending beam is the dynamic specimen of its supports, notches and load band", "[abi][dynamics][preset]") {
  // 80 x 16 points at h = 3.125 mm (the cells span 0.25 x 0.05 m), eps = 3 h, two notches.
  constexpr std::uint64_t nx = 80, ny = 16;
  constexpr double h = 3.125e-3, eps = 3 * h, X = 0.5 * (0.25 - h), Y = 0.5 * (0.05 - h);
  Session preset, spelled;
  setUpCoarseScene(preset, PERISTEP_SCENE_BENDING_TWO_NOTCHES);
  // Supports: u_y held on the cells within eps of the bottom face, 0.025 +- 0.01 m from each end. Notches:
  // 0.015 m deep, 0.02 m either side of the middle. Load: the top row of cells (the 0.75 mm band is thinner
  // than a cell, so the row takes the band's resultant: b scaled by 0.75 mm / h), a hat of half-width
  // 0.025 m, f_max = -2.5e14 N/(m^3 s).
  const double face = -Y - h / 2, left = -X - h / 2;
  setUpSpecimen(spelled, nx, ny, 2 * X, 2 * Y, 3.0,
                {{left + 0.015, face, left + 0.035, face + eps * (1 - 1e-9), PERISTEP_GRIP_HELD_Y, 0, 0},
                 {-left - 0.035, face, -left - 0.015, face + eps * (1 - 1e-9), PERISTEP_GRIP_HELD_Y, 0, 0}},
                {{-0.02, face - h / 2, -0.02, face + 0.015}, {0.02, face - h / 2, 0.02, face + 0.015}});
  // The band's numbers as the preset scales them to the grid's beam (here by 1 up to rounding, which a bit
  // for bit comparison sees).
  const double hg = 2 * X / (nx - 1), sx = (2 * X + hg) / 0.25, sy = (2 * Y + hg) / 0.05;
  std::vector<double> rate(nx * ny, 0.0);
  for (std::size_t i = 0; i < nx; ++i) {
    const double x = std::abs(-X + static_cast<double>(i) * hg);
    if (x <= 0.025 * sx) rate[(ny - 1) * nx + i] = (0.75e-3 * sy / hg) * -2.5e14 * (1 - x / (0.025 * sx));
  }
  REQUIRE(spelled.setFloat64(PERISTEP_VR_BODY_FORCE_RATE_Y, rate) == fmi3OK);
  for (Session* s : {&preset, &spelled}) REQUIRE(s->setFloat64(PERISTEP_VR_INTERNAL_TIME_STEP, {0.05e-6}) == fmi3OK);
  const auto a = run(preset, nx * ny, 2, 10e-6), b = run(spelled, nx * ny, 2, 10e-6);
  CHECK(a == b);
  // The supports hold u_y at 0, with equal forces by symmetry (at 20 us the flexural wave still lifts the
  // ends: the force holds them down); u_x of theirs is free.
  const auto uy = spelled.getFloat64(PERISTEP_VR_UY, nx * ny), ux = spelled.getFloat64(PERISTEP_VR_UX, nx * ny);
  const std::size_t support = 2 * nx + 6;  // third row, x = left + 6.5 h = left + 0.0203 m
  CHECK(uy[support] == 0.0);
  CHECK(ux[support] != 0.0);
  const auto ry = spelled.getFloat64(PERISTEP_VR_GRIP_BOX_REACTION_Y, 2);
  CHECK(ry[0] != 0);
  CHECK(ry[1] == Approx(ry[0]).epsilon(1e-9));
}

TEST_CASE("grip boxes, one-component grips and body forces are refused where they do not apply",
          "[abi][specimen][arguments]") {
  Session s;
  setUpCoarseScene(s, PERISTEP_SCENE_SPECIMEN);  // quasi-static, 9 x 9 on the unit square, bottom and top held
  const auto refusedAtInitialization = [&](const std::string& fragment) {
    s.log.clear();
    CHECK(s.initialize(0, 1) == fmi3Error);
    requireOneError(s, "fmi3ExitInitializationMode", fragment);
  };
  SECTION("a grip box on the quasi-static model") {
    REQUIRE(s.setInt64(PERISTEP_VR_GRIP_BOX_HOLD, PERISTEP_GRIP_HELD) == fmi3OK);
    refusedAtInitialization("grip box 0 is given, but grip boxes hold points of specimenModel dynamic only");
  }
  SECTION("a side held in x only on the quasi-static model") {
    REQUIRE(s.setInt64(PERISTEP_VR_GRIP_TOP, PERISTEP_GRIP_HELD_X) == fmi3OK);
    refusedAtInitialization("the top grip holds one component only (heldX, heldY)");
  }
  SECTION("a body force on the elastic model") {
    REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_ELASTIC) == fmi3OK);
    std::vector<double> rate(81, 0.0);
    rate[40] = 1e10;
    REQUIRE(s.setFloat64(PERISTEP_VR_BODY_FORCE_RATE_X, rate) == fmi3OK);
    refusedAtInitialization("a body force (bodyForceRateX, bodyForceRateY) is for specimenModel dynamic only");
  }
  SECTION("a box turned inside out") {
    REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_DYNAMIC) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_GRIP_BOX_HOLD, PERISTEP_GRIP_HELD_Y) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_X0, {0.2}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_X1, {-0.2}) == fmi3OK);
    refusedAtInitialization("grip box 0 [0.2, -0.2] x [0, 0] m needs finite corners with x0 <= x1 and y0 <= y1");
  }
  SECTION("a box that holds no point") {
    REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_DYNAMIC) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_GRIP_BOX_HOLD, PERISTEP_GRIP_HELD) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_X0, {5.0}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOX_X1, {6.0}) == fmi3OK);
    refusedAtInitialization("grip box 0 holds no material point of the specimen");
  }
}
