/* How to build: from the repository root, after `cmake --build build` (a CTest runs these two lines):
 *   cc -std=c99 -Wall -Wextra -Iapi examples/c/embed.c -o embed -ldl -lm
 *   ./embed build/component/fmi/PeriStep.so
 * How to run:   embed <path to PeriStep.so>
 *               e.g. build/component/fmi/PeriStep.so, or binaries/x86_64-linux/PeriStep.so inside an
 *               unpacked PeriStep.fmu (it is a zip archive).
 * What it shows: the life of one PeriStep instance through the plain FMI 3.0 C ABI, without any
 *               importer library: load, instantiate for co-simulation, set the grid (structural
 *               parameters), a material parameter and the random coordinate xi, initialize, take one
 *               step at full load, read the damage field and the L2 error of Test 1, free.
 *               Exit status 0 when every call succeeded and the error is finite. */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "example_support.h"
#include "fmi3FunctionTypes.h"
#include "peristep.h"

enum { NX = 17, NY = 17 };

int main(int argc, char** argv) {
  /* 1. Load the shared library and look up the functions this program calls. */
  void* library = openLibrary(argc, argv);
  if (!library) return argc != 2 ? 2 : 1;
  LOOKUP(fmi3InstantiateCoSimulation)
  LOOKUP(fmi3EnterConfigurationMode)
  LOOKUP(fmi3ExitConfigurationMode)
  LOOKUP(fmi3SetUInt64)
  LOOKUP(fmi3SetFloat64)
  LOOKUP(fmi3GetFloat64)
  LOOKUP(fmi3EnterInitializationMode)
  LOOKUP(fmi3ExitInitializationMode)
  LOOKUP(fmi3DoStep)
  LOOKUP(fmi3Terminate)
  LOOKUP(fmi3FreeInstance)

  /* 2. Instantiate. The token proves the binary and its model description belong together. */
  fmi3Instance instance = fmi3InstantiateCoSimulation("embed", PERISTEP_INSTANTIATION_TOKEN, NULL, fmi3False,
                                                      fmi3True, fmi3False, fmi3False, NULL, 0, NULL, logMessage, NULL);
  if (!instance) {
    fprintf(stderr, "embed: instantiation failed\n");
    return 1;
  }

  /* 3. Structural parameters (the grid) may only change in Configuration Mode. */
  const fmi3ValueReference gridRefs[] = {PERISTEP_VR_NX, PERISTEP_VR_NY};
  const fmi3UInt64 grid[] = {NX, NY};
  CHECK(fmi3EnterConfigurationMode(instance))
  CHECK(fmi3SetUInt64(instance, gridRefs, 2, grid, 2))
  CHECK(fmi3ExitConfigurationMode(instance))

  /* 4. Parameters: Poisson's ratio and the standardized random coordinate xi (an array [nModes]). */
  const fmi3ValueReference nuRef = PERISTEP_VR_POISSON_RATIO, xiRef = PERISTEP_VR_XI;
  const fmi3Float64 nu = 0.25, xi = 1.0;
  CHECK(fmi3SetFloat64(instance, &nuRef, 1, &nu, 1))
  CHECK(fmi3SetFloat64(instance, &xiRef, 1, &xi, 1))

  /* 5. Initialize: the component builds and factorizes its operator here. */
  CHECK(fmi3EnterInitializationMode(instance, fmi3False, 0.0, 0.0, fmi3True, 1.0))
  CHECK(fmi3ExitInitializationMode(instance))

  /* 6. One quasi-static step at full load. */
  const fmi3ValueReference loadRef = PERISTEP_VR_LOAD_FACTOR;
  const fmi3Float64 load = 1.0;
  fmi3Boolean eventHandlingNeeded, terminateSimulation, earlyReturn;
  fmi3Float64 lastSuccessfulTime;
  CHECK(fmi3SetFloat64(instance, &loadRef, 1, &load, 1))
  CHECK(fmi3DoStep(instance, 0.0, 1.0, fmi3True, &eventHandlingNeeded, &terminateSimulation, &earlyReturn,
                   &lastSuccessfulTime))

  /* 7. Outputs: the damage field [ny][nx] (one call, nValues = NX * NY) and the scalar errorL2. */
  static fmi3Float64 damage[NY][NX];
  const fmi3ValueReference damageRef = PERISTEP_VR_DAMAGE, errorRef = PERISTEP_VR_ERROR_L2;
  fmi3Float64 errorL2 = NAN;
  CHECK(fmi3GetFloat64(instance, &damageRef, 1, &damage[0][0], NX * NY))
  CHECK(fmi3GetFloat64(instance, &errorRef, 1, &errorL2, 1))
  double maxDamage = 0;
  for (int j = 0; j < NY; ++j)
    for (int i = 0; i < NX; ++i)
      if (damage[j][i] > maxDamage) maxDamage = damage[j][i];
  printf("Test 1 on %d x %d points, nu = %.2f, xi = %.1f: errorL2 = %.6e m, max damage = %g\n", NX, NY, nu, xi,
         errorL2, maxDamage);

  /* 8. Finish and release everything. */
  CHECK(fmi3Terminate(instance))
  fmi3FreeInstance(instance);
  dlclose(library);
  return isfinite(errorL2) && errorL2 > 0 ? 0 : 1;
}
