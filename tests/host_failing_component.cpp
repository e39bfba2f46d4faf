// A stand-in FMU binary for the host tests: every fmi3 function is PeriStep's own (this library depends
// on it and the loader finds the rest there), except that fmi3DoStep returns fmi3Error, as a component
// refusing a sample does, for an instance whose xi[0] was set above 0.5.
#include <dlfcn.h>

#include <map>

#include "fmi3Functions.h"
#include "peristep.h"

namespace {
std::map<fmi3Instance, bool> refused;  // the host drives one instance at a time, from one thread
}

extern "C" {

FMI3_Export fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                      size_t nValueReferences, const fmi3Float64 values[], size_t nValues) {
  static auto* next = reinterpret_cast<fmi3SetFloat64TYPE*>(dlsym(RTLD_NEXT, "fmi3SetFloat64"));
  if (nValueReferences == 1 && valueReferences[0] == PERISTEP_VR_XI && nValues > 0) refused[instance] = values[0] > 0.5;
  return next(instance, valueReferences, nValueReferences, values, nValues);
}

FMI3_Export fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                                  fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                  fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation,
                                  fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime) {
  static auto* next = reinterpret_cast<fmi3DoStepTYPE*>(dlsym(RTLD_NEXT, "fmi3DoStep"));
  if (refused[instance]) return fmi3Error;
  return next(instance, currentCommunicationPoint, communicationStepSize, noSetFMUStatePriorToCurrentPoint,
              eventHandlingNeeded, terminateSimulation, earlyReturn, lastSuccessfulTime);
}

FMI3_Export void fmi3FreeInstance(fmi3Instance instance) {
  static auto* next = reinterpret_cast<fmi3FreeInstanceTYPE*>(dlsym(RTLD_NEXT, "fmi3FreeInstance"));
  refused.erase(instance);
  next(instance);
}

}  // extern "C"
