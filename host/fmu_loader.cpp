#include "fmu_loader.hpp"

#include <dlfcn.h>

#include <string>

#include "host_errors.hpp"

namespace peristep::host {

FmuLibrary::FmuLibrary(const std::filesystem::path& sharedLibrary) : path_(sharedLibrary) {
  // RTLD_LOCAL: two FMUs (or two copies of one) must not resolve each other's symbols.
  // RTLD_NODELETE: the component's OpenMP worker threads outlive its instances (they idle in libgomp,
  // which only the component loads); unmapping the library under them at dlclose crashes the process.
  handle_ = dlopen(sharedLibrary.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (!handle_) {
    const char* why = dlerror();
    throw InputError(sharedLibrary.string() + ": cannot load the FMU binary: " + (why ? why : "unknown error"));
  }
  std::string missing;
#define PERISTEP_HOST_FMI3_LOOKUP(name)                                                   \
  api_.name = reinterpret_cast<fmi3##name##TYPE*>(dlsym(handle_, "fmi3" #name));          \
  if (!api_.name) missing += (missing.empty() ? "" : ", ") + std::string("fmi3" #name);
  PERISTEP_HOST_FMI3_FUNCTIONS(PERISTEP_HOST_FMI3_LOOKUP)
#undef PERISTEP_HOST_FMI3_LOOKUP
  if (!missing.empty()) {
    dlclose(handle_);
    throw InputError(sharedLibrary.string() + ": the FMU binary does not export " + missing);
  }
}

FmuLibrary::~FmuLibrary() { dlclose(handle_); }

}  // namespace peristep::host
