/* What the C examples share: opening the library, the log callback and two macros, LOOKUP (a function of the loaded library
 * by name, into a local of the FMI type; needs `library`) and CHECK (a call that must return fmi3OK).
 * Both return 1 from main with a message on failure. */
#ifndef example_support_h
#define example_support_h

#include <dlfcn.h>
#include <stdio.h>

#include "fmi3FunctionTypes.h"

/* The component reports problems through this callback: print them. */
static void logMessage(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
  (void)env;
  fprintf(stderr, "PeriStep [%s, status %d]: %s\n", category, (int)status, message);
}

/* The library named by the one command-line argument, dlopen'ed; NULL (with a message) when it cannot be. */
static void* openLibrary(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s <path to PeriStep.so>\n", argv[0]);
    return NULL;
  }
  void* library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!library) fprintf(stderr, "%s: %s\n", argv[0], dlerror());
  return library;
}

/* dlsym returns void*; POSIX allows reading it into a function pointer through its address. */
#define LOOKUP(name)                                            \
  name##TYPE* name;                                             \
  *(void**)(&name) = dlsym(library, #name);                     \
  if (!name) {                                                  \
    fprintf(stderr, "%s is not exported\n", #name);             \
    return 1;                                                   \
  }

#define CHECK(call)                                             \
  if ((call) != fmi3OK) {                                       \
    fprintf(stderr, "%s failed\n", #call);                      \
    return 1;                                                   \
  }

#endif /* example_support_h */
