/* FMI 3.0 platform types (standard Section 2.2.2), declared for PeriStep.
   The typedefs must match the standard exactly: importers compiled against the official headers
   exchange these types with PeriStep.so by value and by pointer. */
#ifndef fmi3PlatformTypes_h
#define fmi3PlatformTypes_h

#include <stdbool.h>
#include <stdint.h>

/* Opaque handles */
typedef void* fmi3Instance;            /* one FMU instance */
typedef void* fmi3InstanceEnvironment; /* the importer's context, passed back to its callbacks */
typedef void* fmi3FMUState;            /* a copy of an instance's internal state */

/* Identifies a variable of the model description */
typedef uint32_t fmi3ValueReference;

/* Variable types */
typedef float fmi3Float32;
typedef double fmi3Float64;
typedef int8_t fmi3Int8;
typedef uint8_t fmi3UInt8;
typedef int16_t fmi3Int16;
typedef uint16_t fmi3UInt16;
typedef int32_t fmi3Int32;
typedef uint32_t fmi3UInt32;
typedef int64_t fmi3Int64;
typedef uint64_t fmi3UInt64;
typedef bool fmi3Boolean;
typedef char fmi3Char;
typedef const fmi3Char* fmi3String; /* NUL-terminated UTF-8 */
typedef uint8_t fmi3Byte;
typedef const fmi3Byte* fmi3Binary; /* length passed separately */
typedef bool fmi3Clock;

#define fmi3True true
#define fmi3False false

#define fmi3ClockActive true
#define fmi3ClockInactive false

#endif /* fmi3PlatformTypes_h */
