#pragma once
// Each built-in scene set up on a coarse grid through the C ABI (Configuration Mode and parameters, not
// yet initialized), for tests that run every scene: the point grids of the quasi-static scenes at 9 x 9
// (glass-ceramic: the paper's plate at h = 16 um), 001's Plexiglass square at eps = 8 mm, h = eps/2, and
// 001's beam at h = 3.125 mm. internalTimeStep stays 0: the dynamic scenes take 001's steps. The 1D bar of
// 002 (no image outputs: 2 x 2) with 16 bonds, pulled monotonically by loadFactor.
#include <catch2/catch.hpp>
#include <string>

#include "fmi_abi_support.hpp"

// A communication step that fits the scene: one MD frame interval for learnedFracture (it steps whole
// frames), 2 us for the dynamic scenes (their descriptions start with "Dynamic"), 0.25 s for the others.
inline double coarseStep(std::int64_t scene, const std::string& description) {
  if (scene == PERISTEP_SCENE_LEARNED_FRACTURE) return 4.95e-14;
  return description.rfind("Dynamic", 0) == 0 ? 2e-6 : 0.25;
}

inline void setUpCoarseScene(Session& s, std::int64_t scene) {
  const auto grid = [&](std::uint64_t nx, std::uint64_t ny, std::uint64_t modes) {
    REQUIRE(s.configure(nx, ny, modes) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_SCENE, scene) == fmi3OK);
  };
  const auto domain = [&](double Lx, double Ly, double poissonRatio) {
    REQUIRE(s.setFloat64(PERISTEP_VR_LX, {Lx}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LY, {Ly}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {poissonRatio}) == fmi3OK);
  };
  switch (scene) {
    case PERISTEP_SCENE_SMOOTH: grid(9, 9, 1); return;
    case PERISTEP_SCENE_COMPOSITE:
    case PERISTEP_SCENE_INTERFACE_CRACK:
    case PERISTEP_SCENE_KL_PLATE: grid(9, 9, 2); return;
    case PERISTEP_SCENE_PATCH_TEST: grid(9, 9, 1); return;
    case PERISTEP_SCENE_SPECIMEN: grid(9, 9, 1); return;  // the start values: a glass plate pulled at the top
    case PERISTEP_SCENE_GLASS_CERAMIC:  // pure glass, which breaks from an opening of about 0.15 um
      grid(51, 26, 1);
      domain(800e-6, 400e-6, 0.25);
      REQUIRE(s.setFloat64(PERISTEP_VR_CRYSTAL_FRACTION, {0.0}) == fmi3OK);
      return;
    case PERISTEP_SCENE_PLEXIGLASS_CRACK:
      grid(25, 25, 1);
      domain(0.096, 0.096, 0.25);  // h = 4 mm: the cells span 0.1 m
      REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {2.0}) == fmi3OK);
      return;
    case PERISTEP_SCENE_LEARNED_FRACTURE: grid(20, 20, 1); return;  // sample III at h = 5 A
    case PERISTEP_SCENE_GAMUT_BAR:
      grid(2, 2, 1);
      REQUIRE(s.setUInt64(PERISTEP_VR_GAMUT_BONDS, 16) == fmi3OK);
      return;
    case PERISTEP_SCENE_BENDING_ONE_NOTCH:
    case PERISTEP_SCENE_BENDING_TWO_NOTCHES:
      grid(80, 16, 1);
      domain(0.25 - 3.125e-3, 0.05 - 3.125e-3, 0.25);  // h = 3.125 mm: the cells span 0.25 x 0.05 m
      return;
  }
  FAIL("no coarse set-up for scene " << scene);
}
