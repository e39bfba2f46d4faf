#pragma once
// The component's shared library, opened with dlopen, and the fmi3* functions the host calls,
// looked up by their standard names. Only the public C headers in api/ describe them.
#include <filesystem>

#include "fmi3FunctionTypes.h"

namespace peristep::host {

// Every fmi3 function the host uses; X(name) expands once per function.
#define PERISTEP_HOST_FMI3_FUNCTIONS(X)                                                                     \
  X(GetVersion) X(SetDebugLogging) X(InstantiateCoSimulation) X(FreeInstance) X(EnterConfigurationMode)     \
  X(ExitConfigurationMode) X(EnterInitializationMode) X(ExitInitializationMode) X(DoStep) X(Terminate)      \
  X(GetFloat32) X(GetFloat64) X(GetInt8) X(GetUInt8) X(GetInt16) X(GetUInt16) X(GetInt32) X(GetUInt32)     \
  X(GetInt64) X(GetUInt64) X(GetBoolean)                                                                    \
  X(SetFloat32) X(SetFloat64) X(SetInt8) X(SetUInt8) X(SetInt16) X(SetUInt16) X(SetInt32) X(SetUInt32)     \
  X(SetInt64) X(SetUInt64) X(SetBoolean)

struct Fmi3Api {
#define PERISTEP_HOST_FMI3_POINTER(name) fmi3##name##TYPE* name = nullptr;
  PERISTEP_HOST_FMI3_FUNCTIONS(PERISTEP_HOST_FMI3_POINTER)
#undef PERISTEP_HOST_FMI3_POINTER
};

class FmuLibrary {
 public:
  // Throws InputError when the library cannot be loaded or lacks one of the functions above.
  explicit FmuLibrary(const std::filesystem::path& sharedLibrary);
  ~FmuLibrary();
  FmuLibrary(const FmuLibrary&) = delete;
  FmuLibrary& operator=(const FmuLibrary&) = delete;

  const Fmi3Api& api() const { return api_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  void* handle_ = nullptr;
  Fmi3Api api_;
};

}  // namespace peristep::host
