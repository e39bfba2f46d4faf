/* PeriStep's public constants for importers written in C, C++ or Python (ctypes): value references
   of every variable in modelDescription.xml, the values of its enumerations, and the instantiation
   token. The names and numbers are stable; new variables get new numbers. */
#ifndef peristep_h
#define peristep_h

#define PERISTEP_MODEL_IDENTIFIER "PeriStep"
/* Must be passed unchanged to fmi3InstantiateCoSimulation (it is also in modelDescription.xml). */
#define PERISTEP_INSTANTIATION_TOKEN "{8c4f2b7e-3d91-4a6c-b5e0-7f12a9d3c648}"

/* Value references. Arrays [ny][nx] are images stored row by row (x varies fastest). */
enum PeriStepValueReference {
  PERISTEP_VR_TIME = 0, /* independent variable (s); read-only */

  /* structural parameters (set in Configuration Mode) */
  PERISTEP_VR_NX = 1,      /* UInt64: points per side in x */
  PERISTEP_VR_NY = 2,      /* UInt64: points per side in y */
  PERISTEP_VR_NMODES = 3,  /* UInt64: length of xi */

  /* parameters */
  PERISTEP_VR_SCENE = 10,            /* Enumeration (fmi3Get/SetInt64): enum PeriStepScene */
  PERISTEP_VR_LX = 11,               /* Float64, m */
  PERISTEP_VR_LY = 12,               /* Float64, m */
  PERISTEP_VR_DELTA_OVER_H = 13,     /* Float64 */
  PERISTEP_VR_POISSON_RATIO = 14,    /* Float64 */
  PERISTEP_VR_MODULUS_CONTRAST = 15, /* Float64 */
  PERISTEP_VR_JITTER = 16,           /* Float64, fraction of h */
  PERISTEP_VR_SEED = 17,             /* UInt64 */
  PERISTEP_VR_LINEAR_SOLVER = 18,    /* Enumeration (fmi3Get/SetInt64): enum PeriStepLinearSolver */
  PERISTEP_VR_XI = 19,               /* Float64 [nModes] */
  PERISTEP_VR_CRYSTAL_FRACTION = 24, /* Float64: glass-ceramic crystal area fraction f */

  /* calculated parameters */
  PERISTEP_VR_XI_DISTRIBUTION = 20, /* Int32 [nModes]: enum PeriStepXiDistribution */
  PERISTEP_VR_XI_SCALE = 21,        /* Float64 [nModes] */
  PERISTEP_VR_X = 22,               /* Float64 [ny][nx], m */
  PERISTEP_VR_Y = 23,               /* Float64 [ny][nx], m */

  /* input */
  PERISTEP_VR_LOAD_FACTOR = 30,       /* Float64 */
  PERISTEP_VR_LOAD_DISPLACEMENT = 31, /* Float64, m: glass-ceramic opening U_D */

  /* outputs */
  PERISTEP_VR_UX = 40,              /* Float64 [ny][nx], m */
  PERISTEP_VR_UY = 41,              /* Float64 [ny][nx], m */
  PERISTEP_VR_DAMAGE = 42,          /* Float64 [ny][nx] */
  PERISTEP_VR_YOUNGS_MODULUS = 43,  /* Float64 [ny][nx], Pa */
  PERISTEP_VR_REACTION_FORCE = 50,  /* Float64, N/m */
  PERISTEP_VR_CRACK_LENGTH = 51,    /* Float64, m */
  PERISTEP_VR_BROKEN_BONDS = 52,    /* Float64 */
  PERISTEP_VR_STRAIN_ENERGY = 53,   /* Float64, J/m */
  PERISTEP_VR_FRACTURE_ENERGY = 54, /* Float64, J/m */
  PERISTEP_VR_TOUGHNESS_KIC = 55,   /* Float64, Pa m^0.5 */
  PERISTEP_VR_ERROR_L2 = 56         /* Float64, m */
};

/* Values of the enumeration PeriStep.Scene (variable "scene") */
enum PeriStepScene {
  PERISTEP_SCENE_SMOOTH = 1,          /* smooth manufactured solution (Fan et al., Test 1) */
  PERISTEP_SCENE_COMPOSITE = 2,       /* bimaterial composite (Fan et al., Test 2) */
  PERISTEP_SCENE_INTERFACE_CRACK = 3, /* crack on a bimaterial interface (Fan et al., Test 3) */
  PERISTEP_SCENE_GLASS_CERAMIC = 4    /* pre-cracked glass-ceramic plate (Fan et al., Sec. 5) */
};

/* Values of the enumeration PeriStep.LinearSolver (variable "linearSolver") */
enum PeriStepLinearSolver {
  PERISTEP_LINEAR_SOLVER_UMFPACK = 1,
  PERISTEP_LINEAR_SOLVER_UMFPACK_AMD = 2,
  PERISTEP_LINEAR_SOLVER_SPARSE_LU = 3,
  PERISTEP_LINEAR_SOLVER_BICGSTAB_ILUT = 4
};

/* Values of the array "xiDistribution": the law of each standardized coordinate */
enum PeriStepXiDistribution {
  PERISTEP_XI_NORMAL = 0,
  PERISTEP_XI_UNIFORM = 1
};

#endif /* peristep_h */
