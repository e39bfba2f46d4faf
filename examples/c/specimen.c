/* How to build: from the repository root, after `cmake --build build` (a CTest runs it):
 *   cc -std=c99 -Wall -Wextra -Iapi examples/c/specimen.c -o specimen -ldl -lm
 *   ./specimen build/component/fmi/PeriStep.so
 * What it shows: your own specimen through the plain FMI 3.0 C ABI. A picture (an array of strings) becomes
 *               the material maps of the "specimen" scene: '.' matrix (E = 1 GPa, G = 1 J/m^2), '#' an
 *               inclusion ten times as stiff and as tough, ' ' a hole (E = 0: Void). One inclined pre-crack
 *               segment from the left edge; the bottom grip holds, the top grip pulls up by
 *               loadFactor * 1e-5 m. Each step raises loadFactor and prints the top grip's reaction; at the
 *               end the damage picture ('X' cracked). Exit status 0 when the crack grew from the notch. */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>

#include "example_support.h"
#include "fmi3FunctionTypes.h"
#include "peristep.h"

enum { NX = 33, NY = 17 };
static const double H = 0.1; /* grid spacing [m]: the plate is (NX-1) H x (NY-1) H */
static const double NOTCH[4] = {-1.6, -0.3, -1.0, 0.1}; /* x0, y0, x1, y1 [m] */

/* Top row first, as it is drawn. */
static const char* const PICTURE[NY] = {
    ".................................", ".................................", ".................................",
    ".................................", "...........................   ...", "..........................     ..",
    "...................###.....   ...", "..................#####..........", ".................#######.........",
    "..................#####..........", "...................###...........", ".................................",
    ".................................", ".................................", ".................................",
    ".................................", "................................."};

/* The character of image point (i, j): image row 0 is the bottom (y = -Ly/2), the picture's last row. */
static char at(int i, int j) { return PICTURE[NY - 1 - j][i]; }

int main(int argc, char** argv) {
  void* library = openLibrary(argc, argv);
  if (!library) return argc != 2 ? 2 : 1;
  LOOKUP(fmi3InstantiateCoSimulation)
  LOOKUP(fmi3EnterConfigurationMode)
  LOOKUP(fmi3ExitConfigurationMode)
  LOOKUP(fmi3SetUInt64)
  LOOKUP(fmi3SetInt64)
  LOOKUP(fmi3SetFloat64)
  LOOKUP(fmi3GetFloat64)
  LOOKUP(fmi3EnterInitializationMode)
  LOOKUP(fmi3ExitInitializationMode)
  LOOKUP(fmi3DoStep)
  LOOKUP(fmi3Terminate)
  LOOKUP(fmi3FreeInstance)

  fmi3Instance instance = fmi3InstantiateCoSimulation("specimen", PERISTEP_INSTANTIATION_TOKEN, NULL, fmi3False,
                                                      fmi3True, fmi3False, fmi3False, NULL, 0, NULL, logMessage, NULL);
  if (!instance) {
    fprintf(stderr, "specimen: instantiation failed\n");
    return 1;
  }

  /* 1. Structural parameters: the grid and the number of pre-crack segments. */
  const fmi3ValueReference structure[] = {PERISTEP_VR_NX, PERISTEP_VR_NY, PERISTEP_VR_NCRACKS};
  const fmi3UInt64 sizes[] = {NX, NY, 1};
  CHECK(fmi3EnterConfigurationMode(instance))
  CHECK(fmi3SetUInt64(instance, structure, 3, sizes, 3))
  CHECK(fmi3ExitConfigurationMode(instance))

  /* 2. The scene, the plate, the material maps [ny][nx] from the picture, the notch, the top grip's pull.
   *    Everything else keeps its start value: left and right free, bottom held, nu = 0.25. */
  static fmi3Float64 E[NY][NX], G[NY][NX];
  for (int j = 0; j < NY; ++j)
    for (int i = 0; i < NX; ++i) {
      E[j][i] = at(i, j) == '#' ? 1e10 : at(i, j) == ' ' ? 0.0 : 1e9;
      G[j][i] = at(i, j) == '#' ? 10.0 : 1.0;
    }
  const fmi3ValueReference sceneRef = PERISTEP_VR_SCENE;
  const fmi3Int64 scene = PERISTEP_SCENE_SPECIMEN;
  CHECK(fmi3SetInt64(instance, &sceneRef, 1, &scene, 1))
  const fmi3ValueReference plateRefs[] = {PERISTEP_VR_LX, PERISTEP_VR_LY, PERISTEP_VR_CRACK_X0, PERISTEP_VR_CRACK_Y0,
                                          PERISTEP_VR_CRACK_X1, PERISTEP_VR_CRACK_Y1, PERISTEP_VR_GRIP_TOP_UY};
  const fmi3Float64 plate[] = {H * (NX - 1), H * (NY - 1), NOTCH[0], NOTCH[1], NOTCH[2], NOTCH[3], 1e-5};
  CHECK(fmi3SetFloat64(instance, plateRefs, 7, plate, 7))
  const fmi3ValueReference eRef = PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, gRef = PERISTEP_VR_MATERIAL_FRACTURE_ENERGY;
  CHECK(fmi3SetFloat64(instance, &eRef, 1, &E[0][0], NX * NY))
  CHECK(fmi3SetFloat64(instance, &gRef, 1, &G[0][0], NX * NY))

  /* 3. Initialize (the component builds the cloud, bonds and pre-crack here), then raise the load: each
   *    step breaks bonds until equilibrium at its loadFactor. */
  CHECK(fmi3EnterInitializationMode(instance, fmi3False, 0.0, 0.0, fmi3True, 40.0))
  CHECK(fmi3ExitInitializationMode(instance))
  const fmi3ValueReference loadRef = PERISTEP_VR_LOAD_FACTOR, damageRef = PERISTEP_VR_DAMAGE,
                           reactionRef = PERISTEP_VR_REACTION_TOP_Y;
  static fmi3Float64 damage[NY][NX];
  double front = -INFINITY;
  for (int step = 0; step <= 20 && front < 1.0; ++step) {
    const fmi3Float64 load = 2.0 + 0.5 * step;
    fmi3Boolean eventHandlingNeeded, terminateSimulation, earlyReturn;
    fmi3Float64 lastSuccessfulTime, reaction;
    CHECK(fmi3SetFloat64(instance, &loadRef, 1, &load, 1))
    CHECK(fmi3DoStep(instance, step, 1.0, fmi3True, &eventHandlingNeeded, &terminateSimulation, &earlyReturn,
                     &lastSuccessfulTime))
    CHECK(fmi3GetFloat64(instance, &damageRef, 1, &damage[0][0], NX * NY))
    CHECK(fmi3GetFloat64(instance, &reactionRef, 1, &reaction, 1))
    for (int j = 0; j < NY; ++j)
      for (int i = 0; i < NX; ++i)
        if (damage[j][i] > 0.3 && -0.5 * H * (NX - 1) + H * i > front) front = -0.5 * H * (NX - 1) + H * i;
    printf("loadFactor %5.2f: top reaction %10.4g N/m, crack front x = %5.2f m\n", load, reaction, front);
  }
  for (int j = NY - 1; j >= 0; --j) {
    for (int i = 0; i < NX; ++i) putchar(damage[j][i] > 0.3 ? 'X' : at(i, j));
    putchar('\n');
  }
  CHECK(fmi3Terminate(instance))
  fmi3FreeInstance(instance);
  dlclose(library);
  if (front <= NOTCH[2] + H) {
    fprintf(stderr, "specimen: the crack did not grow from the notch\n");
    return 1;
  }
  printf("the crack grew from the notch to x = %.2f m\n", front);
  return 0;
}
