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
  PERISTEP_VR_NCRACKS = 4, /* UInt64: pre-cracks of the specimen scene (length of crackX0 ...) */

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
  PERISTEP_VR_CORRELATION_LENGTH = 25, /* Float64, m: KL plate */
  PERISTEP_VR_FIELD_STD = 26,          /* Float64: KL plate, standard deviation of the field g */
  PERISTEP_VR_COVARIANCE = 27,         /* Enumeration: enum PeriStepCovariance */
  PERISTEP_VR_FIELD_TRANSFORM = 28,    /* Enumeration: enum PeriStepFieldTransform */
  PERISTEP_VR_PCA_REALIZATIONS = 29,   /* UInt64: glass-ceramic PCA field from this many realizations; 0: none */

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
  PERISTEP_VR_EXACT_MEAN_UX = 44,   /* Float64 [ny][nx], m: mean over xi of the exact solution */
  PERISTEP_VR_EXACT_MEAN_UY = 45,   /* Float64 [ny][nx], m */
  PERISTEP_VR_EXACT_STD_UX = 46,    /* Float64 [ny][nx], m: standard deviation over xi */
  PERISTEP_VR_EXACT_STD_UY = 47,    /* Float64 [ny][nx], m */
  PERISTEP_VR_HAS_EXACT_MOMENTS = 48, /* Int32: 1 when the four fields above are the scene's exact moments */
  PERISTEP_VR_RETAINED_VARIANCE = 49, /* Float64: variance fraction of the retained KL / PCA modes */
  PERISTEP_VR_REACTION_FORCE = 50,  /* Float64, N/m */
  PERISTEP_VR_CRACK_LENGTH = 51,    /* Float64, m */
  PERISTEP_VR_BROKEN_BONDS = 52,    /* Float64 */
  PERISTEP_VR_STRAIN_ENERGY = 53,   /* Float64, J/m */
  PERISTEP_VR_FRACTURE_ENERGY = 54, /* Float64, J/m */
  PERISTEP_VR_TOUGHNESS_KIC = 55,   /* Float64, Pa m^0.5 */
  PERISTEP_VR_ERROR_L2 = 56,        /* Float64, m */
  PERISTEP_VR_KINETIC_ENERGY = 57,  /* Float64, J/m: dynamic scenes */
  PERISTEP_VR_EXTERNAL_WORK = 58,   /* Float64, J/m: work of the loads since the start (dynamic scenes) */
  PERISTEP_VR_FORCE_EVALUATIONS = 59, /* Float64: force evaluations spent by the time integrator */

  /* parameters of the dynamic scenes (5-7) */
  PERISTEP_VR_TIME_INTEGRATOR = 60,       /* Enumeration (fmi3Get/SetInt64): enum PeriStepTimeIntegrator */
  PERISTEP_VR_INTERNAL_TIME_STEP = 61,    /* Float64, s: central difference step; 0: the scene's */
  PERISTEP_VR_INTEGRATOR_TOLERANCE = 62,  /* Float64: relative tolerance of the SUNDIALS integrators */

  /* bounds on the work one call may start (refused up front with the estimate) */
  PERISTEP_VR_MEMORY_BUDGET = 63,     /* UInt64, bytes: estimated set-up memory; 0: 3/4 of usable memory */
  PERISTEP_VR_SET_UP_TIME_LIMIT = 64, /* Float64, s: estimated set-up time; 0: no limit */
  PERISTEP_VR_MAX_INTERNAL_STEPS = 65, /* UInt64: internal time steps per fmi3DoStep; 0: no limit */

  /* material constants of the built-in scenes (start values: the papers'); nu is poissonRatio */
  PERISTEP_VR_GLASS_YOUNGS_MODULUS = 70,     /* Float64, Pa: glass-ceramic, glass phase E1 (000 Table 1) */
  PERISTEP_VR_CRYSTAL_YOUNGS_MODULUS = 71,   /* Float64, Pa: glass-ceramic, crystal phase E2 */
  PERISTEP_VR_GLASS_FRACTURE_ENERGY = 72,    /* Float64, J/m^2: glass-ceramic, glass phase G1 */
  PERISTEP_VR_CRYSTAL_FRACTURE_ENERGY = 73,  /* Float64, J/m^2: glass-ceramic, crystal phase G2 */
  PERISTEP_VR_BULK_MODULUS = 74,             /* Float64, Pa: dynamic scenes, K (001 Table 1) */
  PERISTEP_VR_CRITICAL_ENERGY_RELEASE_RATE = 75, /* Float64, J/m^2: dynamic scenes, G_c */
  PERISTEP_VR_DENSITY = 76,                  /* Float64, kg/m^3: dynamic scenes, rho */

  /* the specimen scene (PERISTEP_SCENE_SPECIMEN): material maps, pre-cracks and grips */
  PERISTEP_VR_MATERIAL_DENSITY = 78,         /* Float64 [ny][nx], kg/m^3: read by the dynamic model */
  PERISTEP_VR_MATERIAL_FIELD = 79,           /* Enumeration: enum PeriStepMaterialField */
  PERISTEP_VR_MATERIAL_YOUNGS_MODULUS = 80,  /* Float64 [ny][nx], Pa: 0 = Void (a hole) */
  PERISTEP_VR_MATERIAL_POISSON_RATIO = 81,   /* Float64 [ny][nx] */
  PERISTEP_VR_MATERIAL_FRACTURE_ENERGY = 82, /* Float64 [ny][nx], J/m^2 */
  PERISTEP_VR_CRACK_X0 = 83,                 /* Float64 [nCracks], m: pre-crack segments (x0, y0)-(x1, y1) */
  PERISTEP_VR_CRACK_Y0 = 84,
  PERISTEP_VR_CRACK_X1 = 85,
  PERISTEP_VR_CRACK_Y1 = 86,
  PERISTEP_VR_GRIP_LEFT = 87,                /* Enumeration: enum PeriStepGrip */
  PERISTEP_VR_GRIP_RIGHT = 88,
  PERISTEP_VR_GRIP_BOTTOM = 89,
  PERISTEP_VR_GRIP_TOP = 90,
  PERISTEP_VR_GRIP_LEFT_UX = 91,             /* Float64, m: displacement of a held grip at loadFactor 1 */
  PERISTEP_VR_GRIP_LEFT_UY = 92,
  PERISTEP_VR_GRIP_RIGHT_UX = 93,
  PERISTEP_VR_GRIP_RIGHT_UY = 94,
  PERISTEP_VR_GRIP_BOTTOM_UX = 95,
  PERISTEP_VR_GRIP_BOTTOM_UY = 96,
  PERISTEP_VR_GRIP_TOP_UX = 97,
  PERISTEP_VR_GRIP_TOP_UY = 98,
  PERISTEP_VR_SPECIMEN_MODEL = 99,           /* Enumeration: enum PeriStepSpecimenModel */
  PERISTEP_VR_REACTION_LEFT_X = 100,         /* Float64, N/m: force of each held grip on the specimen */
  PERISTEP_VR_REACTION_LEFT_Y = 101,
  PERISTEP_VR_REACTION_RIGHT_X = 102,
  PERISTEP_VR_REACTION_RIGHT_Y = 103,
  PERISTEP_VR_REACTION_BOTTOM_X = 104,
  PERISTEP_VR_REACTION_BOTTOM_Y = 105,
  PERISTEP_VR_REACTION_TOP_X = 106,
  PERISTEP_VR_REACTION_TOP_Y = 107,
  PERISTEP_VR_GRIP_LEFT_VX = 130,            /* Float64, m/s: velocity of a held grip at loadFactor 1 (dynamic) */
  PERISTEP_VR_GRIP_LEFT_VY = 131,
  PERISTEP_VR_GRIP_RIGHT_VX = 132,
  PERISTEP_VR_GRIP_RIGHT_VY = 133,
  PERISTEP_VR_GRIP_BOTTOM_VX = 134,
  PERISTEP_VR_GRIP_BOTTOM_VY = 135,
  PERISTEP_VR_GRIP_TOP_VX = 136,
  PERISTEP_VR_GRIP_TOP_VY = 137,

  /* the 1D deformation-gamut bar of paper 002 (PERISTEP_SCENE_GAMUT_BAR); seed picks the realization */
  PERISTEP_VR_GAMUT_MATERIAL = 110,      /* Enumeration: enum PeriStepGamutMaterial */
  PERISTEP_VR_GAMUT_GRID = 111,          /* Enumeration: enum PeriStepGamutGrid */
  PERISTEP_VR_GAMUT_BONDS = 112,         /* UInt64: local bonds (bonds + 1 points) */
  PERISTEP_VR_SCATTER_DENOMINATOR = 113, /* Float64: the /10 of 002:(26) */
  PERISTEP_VR_WEIBULL_SHAPE = 114,       /* Float64: shape of the Weibull draw of 002:(26) */
  PERISTEP_VR_GAMUT_PROTOCOL = 115,      /* Enumeration: enum PeriStepGamutProtocol */
  PERISTEP_VR_BAR_STRESS = 120,          /* Float64, Pa: end force over area */
  PERISTEP_VR_BAR_STRAIN = 121,          /* Float64: end displacement over length */
  PERISTEP_VR_CYCLIC_EXPONENT = 122,     /* Float64: n' of the cyclic protocol (0 until it has finished) */
  PERISTEP_VR_CYCLIC_COEFFICIENT = 123,  /* Float64, Pa: K' of the cyclic protocol (0 until it has finished) */

  /* the learned LPS model of paper 003 predicting an MD fracture sample (PERISTEP_SCENE_LEARNED_FRACTURE) */
  PERISTEP_VR_LEARNED_SAMPLE = 140,            /* Enumeration: enum PeriStepLearnedSample */
  PERISTEP_VR_LEARNED_CRITICAL_STRETCH = 141,  /* Float64: s0 at h = 5 A (003: 0.11) */
  PERISTEP_VR_PREDICTION_ERROR_U = 142,        /* Float64: displacement error against the MD frames so far */
  PERISTEP_VR_PREDICTION_ERROR_DAMAGE = 143,   /* Float64: damage error against the MD frames so far */

  /* the specimen scene, quasi-static models: displacement gradient of every held collar at loadFactor 1 */
  PERISTEP_VR_COLLAR_DUX_DX = 144, /* Float64 */
  PERISTEP_VR_COLLAR_DUX_DY = 145, /* Float64 */
  PERISTEP_VR_COLLAR_DUY_DX = 146, /* Float64 */
  PERISTEP_VR_COLLAR_DUY_DY = 147, /* Float64 */
  PERISTEP_VR_EXACT_SOLUTION = 148, /* Enumeration: enum PeriStepExactSolution (elastic model) */

  /* the specimen scene, dynamic model: grip boxes (held points inside a rectangle) and a body force */
  PERISTEP_VR_NGRIP_BOXES = 149,            /* UInt64, structural: length of the gripBox arrays */
  PERISTEP_VR_GRIP_BOX_X0 = 150,            /* Float64[nGripBoxes], m: the box [x0, x1] x [y0, y1] */
  PERISTEP_VR_GRIP_BOX_Y0 = 151,
  PERISTEP_VR_GRIP_BOX_X1 = 152,
  PERISTEP_VR_GRIP_BOX_Y1 = 153,
  PERISTEP_VR_GRIP_BOX_HOLD = 154,          /* Enumeration[nGripBoxes]: enum PeriStepGrip (free: no box) */
  PERISTEP_VR_GRIP_BOX_VX = 155,            /* Float64[nGripBoxes], m/s: velocity at loadFactor 1 */
  PERISTEP_VR_GRIP_BOX_VY = 156,
  PERISTEP_VR_BODY_FORCE_RATE_X = 157,      /* Float64[ny][nx], N/(m3 s): b = loadFactor t rate */
  PERISTEP_VR_BODY_FORCE_RATE_Y = 158,
  PERISTEP_VR_GRIP_BOX_REACTION_X = 159,    /* Float64[nGripBoxes], N/m: force of each box on the specimen */
  PERISTEP_VR_GRIP_BOX_REACTION_Y = 160
};

/* Values of the enumeration PeriStep.Scene (variable "scene") */
enum PeriStepScene {
  PERISTEP_SCENE_SMOOTH = 1,          /* smooth manufactured solution (Fan et al., Test 1) */
  PERISTEP_SCENE_COMPOSITE = 2,       /* bimaterial composite (Fan et al., Test 2) */
  PERISTEP_SCENE_INTERFACE_CRACK = 3, /* crack on a bimaterial interface (Fan et al., Test 3) */
  PERISTEP_SCENE_GLASS_CERAMIC = 4,   /* pre-cracked glass-ceramic plate (Fan et al., Sec. 5) */
  PERISTEP_SCENE_PLEXIGLASS_CRACK = 5,     /* dynamic crack in a Plexiglass square (Jha-Lipton, Sec. 6.1) */
  PERISTEP_SCENE_BENDING_ONE_NOTCH = 6,    /* dynamic three-point bending, one pre-crack (Jha-Lipton, Sec. 6.2) */
  PERISTEP_SCENE_BENDING_TWO_NOTCHES = 7,  /* the same with two pre-cracks */
  PERISTEP_SCENE_KL_PLATE = 8,        /* plate with a Karhunen-Loeve random Young's modulus */
  PERISTEP_SCENE_SPECIMEN = 9,        /* the importer's specimen: material maps, pre-cracks, grips */
  PERISTEP_SCENE_GAMUT_BAR = 10,      /* 1D stochastic deformation-gamut bar (Desai, paper 002) */
  PERISTEP_SCENE_LEARNED_FRACTURE = 11 /* learned LPS model predicting an MD fracture sample (You et al., 003) */
};

/* Values of the enumeration PeriStep.LearnedSample (variable "learnedSample", learnedFracture scene) */
enum PeriStepLearnedSample {
  PERISTEP_LEARNED_TRAINING = 1,     /* sample III, h = 5 A (20 x 20 points) */
  PERISTEP_LEARNED_TEST = 2,         /* sample IV, h = 5 A (20 x 20 points) */
  PERISTEP_LEARNED_TRAINING_FINE = 3 /* sample III, h = 3.17 A (31 x 31 points) */
};

/* Values of the enumeration PeriStep.GamutMaterial (variable "gamutMaterial", gamutBar scene) */
enum PeriStepGamutMaterial {
  PERISTEP_GAMUT_MATERIAL_1 = 1, /* 002 Sec. 4.2, Material 1 */
  PERISTEP_GAMUT_MATERIAL_2 = 2  /* 002 Sec. 4.2, Material 2 */
};

/* Values of the enumeration PeriStep.GamutGrid (variable "gamutGrid", gamutBar scene) */
enum PeriStepGamutGrid {
  PERISTEP_GAMUT_GRID_UNIFORM = 1,   /* equally spaced points */
  PERISTEP_GAMUT_GRID_STOCHASTIC = 2 /* the stochastic grid of 002:(36) */
};

/* Values of the enumeration PeriStep.GamutProtocol (variable "gamutProtocol", gamutBar scene) */
enum PeriStepGamutProtocol {
  PERISTEP_GAMUT_MONOTONIC = 1, /* every step at end stress loadFactor * sigma_f */
  PERISTEP_GAMUT_CYCLIC = 2     /* one force step of the cyclic protocol per fmi3DoStep; then n', K' */
};

/* Values of the enumeration PeriStep.MaterialField (variable "materialField", specimen scene) */
enum PeriStepMaterialField {
  PERISTEP_MATERIAL_MAP = 1,     /* the maps as given */
  PERISTEP_MATERIAL_KL_FIELD = 2,    /* Young's modulus map times the KL factor of xi (as the KL plate's E0 = 1) */
  PERISTEP_MATERIAL_GLASS_CERAMIC = 3 /* the glass-ceramic of 000 Sec. 5 (seed or PCA field), as scene glassCeramic */
};

/* Values of the enumeration PeriStep.ExactSolution (variable "exactSolution", specimen scene) */
enum PeriStepExactSolution {
  PERISTEP_EXACT_NONE = 1,           /* the maps and grips */
  PERISTEP_EXACT_SMOOTH = 2,         /* material, body force and collar data of 000 Test 1 */
  PERISTEP_EXACT_COMPOSITE = 3,      /* those of 000 Test 2 */
  PERISTEP_EXACT_INTERFACE_CRACK = 4 /* those of 000 Test 3 (give its crack as a pre-crack) */
};

/* Values of the enumeration PeriStep.SpecimenModel (variable "specimenModel", specimen scene) */
enum PeriStepSpecimenModel {
  PERISTEP_SPECIMEN_QUASI_STATIC = 1, /* LPS, brittle bonds, equilibrium at every load (Fan et al.) */
  PERISTEP_SPECIMEN_DYNAMIC = 2,      /* state-based model in time, grips at prescribed velocities (Jha-Lipton) */
  PERISTEP_SPECIMEN_ELASTIC = 3       /* LPS without fracture: one factorization, one solve per step (Fan et al.) */
};

/* Values of the enumeration PeriStep.Grip (variables "gripLeft" ... "gripTop" and "gripBoxHold", specimen scene) */
enum PeriStepGrip {
  PERISTEP_GRIP_FREE = 1, /* traction-free side */
  PERISTEP_GRIP_HELD = 2, /* the collar beside the side moves rigidly: by loadFactor * (gripUx, gripUy),
                             or at loadFactor * (gripVx, gripVy) in the dynamic model */
  PERISTEP_GRIP_HELD_X = 3, /* dynamic model: held in x only (at loadFactor * gripVx), free in y */
  PERISTEP_GRIP_HELD_Y = 4  /* dynamic model: held in y only (at loadFactor * gripVy), free in x */
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
  PERISTEP_XI_UNIFORM = 1,
  PERISTEP_XI_UNUSED = 2 /* the scene ignores this entry */
};

/* Values of the enumeration PeriStep.Covariance (variable "covariance") */
enum PeriStepCovariance {
  PERISTEP_COVARIANCE_EXPONENTIAL = 1, /* s^2 exp(-r/l) */
  PERISTEP_COVARIANCE_GAUSSIAN = 2     /* s^2 exp(-r^2/l^2) */
};

/* Values of the enumeration PeriStep.FieldTransform (variable "fieldTransform") */
enum PeriStepFieldTransform {
  PERISTEP_FIELD_AFFINE = 1,     /* E = E0 (1 + g): refused where E <= 0 */
  PERISTEP_FIELD_LOGNORMAL = 2   /* E = E0 exp(g - var/2): positive for every xi */
};

/* Values of the enumeration PeriStep.TimeIntegrator (variable "timeIntegrator", dynamic scenes) */
enum PeriStepTimeIntegrator {
  PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE = 1, /* explicit, fixed step internalTimeStep, stability-checked */
  PERISTEP_INTEGRATOR_ARKODE_ERK = 2,         /* SUNDIALS ARKODE explicit adaptive Runge-Kutta */
  PERISTEP_INTEGRATOR_CVODE_BDF = 3           /* SUNDIALS CVODE BDF, implicit, for stiff problems */
};

#endif /* peristep_h */
