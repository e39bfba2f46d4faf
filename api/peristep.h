/* PeriStep's public constants for importers written in C, C++ or Python (ctypes): the value reference
   of every variable of modelDescription.xml and the values of its enumerations, with the model
   identifier and instantiation token. Generated from the component's declarations
   (modelDescription/generate_api_header.cpp): do not edit. Names and numbers are stable; new
   variables get new numbers. Arrays [ny][nx] are images stored row by row (x varies fastest). */
#ifndef peristep_h
#define peristep_h

#define PERISTEP_MODEL_IDENTIFIER "PeriStep"
/* Must be passed unchanged to fmi3InstantiateCoSimulation (it is also in modelDescription.xml). */
#define PERISTEP_INSTANTIATION_TOKEN "{8c4f2b7e-3d91-4a6c-b5e0-7f12a9d3c648}"

enum PeriStepValueReference {
  PERISTEP_VR_TIME = 0, /* time: Float64, s, independent */
  PERISTEP_VR_NX = 1, /* nx: UInt64, structuralParameter */
  PERISTEP_VR_NY = 2, /* ny: UInt64, structuralParameter */
  PERISTEP_VR_NMODES = 3, /* nModes: UInt64, structuralParameter */
  PERISTEP_VR_NCRACKS = 4, /* nCracks: UInt64, structuralParameter */
  PERISTEP_VR_NGRIP_BOXES = 149, /* nGripBoxes: UInt64, structuralParameter */
  PERISTEP_VR_SCENE = 10, /* scene: Enumeration, parameter */
  PERISTEP_VR_LX = 11, /* Lx: Float64, m, parameter */
  PERISTEP_VR_LY = 12, /* Ly: Float64, m, parameter */
  PERISTEP_VR_DELTA_OVER_H = 13, /* deltaOverH: Float64, parameter */
  PERISTEP_VR_POISSON_RATIO = 14, /* poissonRatio: Float64, parameter */
  PERISTEP_VR_MODULUS_CONTRAST = 15, /* modulusContrast: Float64, parameter */
  PERISTEP_VR_JITTER = 16, /* jitter: Float64, parameter */
  PERISTEP_VR_SEED = 17, /* seed: UInt64, parameter */
  PERISTEP_VR_LINEAR_SOLVER = 18, /* linearSolver: Enumeration, parameter */
  PERISTEP_VR_XI = 19, /* xi: Float64[nModes], parameter */
  PERISTEP_VR_CRYSTAL_FRACTION = 24, /* crystalFraction: Float64, parameter */
  PERISTEP_VR_CORRELATION_LENGTH = 25, /* correlationLength: Float64, m, parameter */
  PERISTEP_VR_FIELD_STD = 26, /* fieldStd: Float64, parameter */
  PERISTEP_VR_COVARIANCE = 27, /* covariance: Enumeration, parameter */
  PERISTEP_VR_FIELD_TRANSFORM = 28, /* fieldTransform: Enumeration, parameter */
  PERISTEP_VR_PCA_REALIZATIONS = 29, /* pcaRealizations: UInt64, parameter */
  PERISTEP_VR_XI_DISTRIBUTION = 20, /* xiDistribution: Int32[nModes], calculatedParameter */
  PERISTEP_VR_XI_SCALE = 21, /* xiScale: Float64[nModes], calculatedParameter */
  PERISTEP_VR_X = 22, /* x: Float64[ny][nx], m, calculatedParameter */
  PERISTEP_VR_Y = 23, /* y: Float64[ny][nx], m, calculatedParameter */
  PERISTEP_VR_LOAD_FACTOR = 30, /* loadFactor: Float64, input */
  PERISTEP_VR_LOAD_DISPLACEMENT = 31, /* loadDisplacement: Float64, m, input */
  PERISTEP_VR_UX = 40, /* ux: Float64[ny][nx], m, output */
  PERISTEP_VR_UY = 41, /* uy: Float64[ny][nx], m, output */
  PERISTEP_VR_DAMAGE = 42, /* damage: Float64[ny][nx], output */
  PERISTEP_VR_YOUNGS_MODULUS = 43, /* youngsModulus: Float64[ny][nx], Pa, output */
  PERISTEP_VR_EXACT_MEAN_UX = 44, /* exactMeanUx: Float64[ny][nx], m, output */
  PERISTEP_VR_EXACT_MEAN_UY = 45, /* exactMeanUy: Float64[ny][nx], m, output */
  PERISTEP_VR_EXACT_STD_UX = 46, /* exactStdUx: Float64[ny][nx], m, output */
  PERISTEP_VR_EXACT_STD_UY = 47, /* exactStdUy: Float64[ny][nx], m, output */
  PERISTEP_VR_HAS_EXACT_MOMENTS = 48, /* hasExactMoments: Int32, output */
  PERISTEP_VR_RETAINED_VARIANCE = 49, /* retainedVariance: Float64, output */
  PERISTEP_VR_REACTION_LEFT_X = 100, /* reactionLeftX: Float64, N/m, output */
  PERISTEP_VR_REACTION_LEFT_Y = 101, /* reactionLeftY: Float64, N/m, output */
  PERISTEP_VR_REACTION_RIGHT_X = 102, /* reactionRightX: Float64, N/m, output */
  PERISTEP_VR_REACTION_RIGHT_Y = 103, /* reactionRightY: Float64, N/m, output */
  PERISTEP_VR_REACTION_BOTTOM_X = 104, /* reactionBottomX: Float64, N/m, output */
  PERISTEP_VR_REACTION_BOTTOM_Y = 105, /* reactionBottomY: Float64, N/m, output */
  PERISTEP_VR_REACTION_TOP_X = 106, /* reactionTopX: Float64, N/m, output */
  PERISTEP_VR_REACTION_TOP_Y = 107, /* reactionTopY: Float64, N/m, output */
  PERISTEP_VR_GRIP_BOX_REACTION_X = 159, /* gripBoxReactionX: Float64[nGripBoxes], N/m, output */
  PERISTEP_VR_GRIP_BOX_REACTION_Y = 160, /* gripBoxReactionY: Float64[nGripBoxes], N/m, output */
  PERISTEP_VR_REACTION_FORCE = 50, /* reactionForce: Float64, N/m, output */
  PERISTEP_VR_CRACK_LENGTH = 51, /* crackLength: Float64, m, output */
  PERISTEP_VR_BROKEN_BONDS = 52, /* brokenBonds: Float64, output */
  PERISTEP_VR_STRAIN_ENERGY = 53, /* strainEnergy: Float64, J/m, output */
  PERISTEP_VR_FRACTURE_ENERGY = 54, /* fractureEnergy: Float64, J/m, output */
  PERISTEP_VR_TOUGHNESS_KIC = 55, /* toughnessKIC: Float64, Pa.m^0.5, output */
  PERISTEP_VR_ERROR_L2 = 56, /* errorL2: Float64, m, output */
  PERISTEP_VR_KINETIC_ENERGY = 57, /* kineticEnergy: Float64, J/m, output */
  PERISTEP_VR_EXTERNAL_WORK = 58, /* externalWork: Float64, J/m, output */
  PERISTEP_VR_FORCE_EVALUATIONS = 59, /* forceEvaluations: Float64, output */
  PERISTEP_VR_TIME_INTEGRATOR = 60, /* timeIntegrator: Enumeration, parameter */
  PERISTEP_VR_INTERNAL_TIME_STEP = 61, /* internalTimeStep: Float64, s, parameter */
  PERISTEP_VR_INTEGRATOR_TOLERANCE = 62, /* integratorTolerance: Float64, parameter */
  PERISTEP_VR_MEMORY_BUDGET = 63, /* memoryBudget: UInt64, parameter */
  PERISTEP_VR_SET_UP_TIME_LIMIT = 64, /* setUpTimeLimit: Float64, s, parameter */
  PERISTEP_VR_MAX_INTERNAL_STEPS = 65, /* maxInternalSteps: UInt64, parameter */
  PERISTEP_VR_MATERIAL_YOUNGS_MODULUS = 80, /* materialYoungsModulus: Float64[ny][nx], Pa, parameter */
  PERISTEP_VR_MATERIAL_FIELD = 79, /* materialField: Enumeration, parameter */
  PERISTEP_VR_EXACT_SOLUTION = 148, /* exactSolution: Enumeration, parameter */
  PERISTEP_VR_MATERIAL_POISSON_RATIO = 81, /* materialPoissonRatio: Float64[ny][nx], parameter */
  PERISTEP_VR_MATERIAL_FRACTURE_ENERGY = 82, /* materialFractureEnergy: Float64[ny][nx], J/m2, parameter */
  PERISTEP_VR_MATERIAL_DENSITY = 78, /* materialDensity: Float64[ny][nx], kg/m3, parameter */
  PERISTEP_VR_CRACK_X0 = 83, /* crackX0: Float64[nCracks], m, parameter */
  PERISTEP_VR_CRACK_Y0 = 84, /* crackY0: Float64[nCracks], m, parameter */
  PERISTEP_VR_CRACK_X1 = 85, /* crackX1: Float64[nCracks], m, parameter */
  PERISTEP_VR_CRACK_Y1 = 86, /* crackY1: Float64[nCracks], m, parameter */
  PERISTEP_VR_GRIP_LEFT = 87, /* gripLeft: Enumeration, parameter */
  PERISTEP_VR_GRIP_RIGHT = 88, /* gripRight: Enumeration, parameter */
  PERISTEP_VR_GRIP_BOTTOM = 89, /* gripBottom: Enumeration, parameter */
  PERISTEP_VR_GRIP_TOP = 90, /* gripTop: Enumeration, parameter */
  PERISTEP_VR_GRIP_LEFT_UX = 91, /* gripLeftUx: Float64, m, parameter */
  PERISTEP_VR_GRIP_LEFT_UY = 92, /* gripLeftUy: Float64, m, parameter */
  PERISTEP_VR_GRIP_RIGHT_UX = 93, /* gripRightUx: Float64, m, parameter */
  PERISTEP_VR_GRIP_RIGHT_UY = 94, /* gripRightUy: Float64, m, parameter */
  PERISTEP_VR_GRIP_BOTTOM_UX = 95, /* gripBottomUx: Float64, m, parameter */
  PERISTEP_VR_GRIP_BOTTOM_UY = 96, /* gripBottomUy: Float64, m, parameter */
  PERISTEP_VR_GRIP_TOP_UX = 97, /* gripTopUx: Float64, m, parameter */
  PERISTEP_VR_GRIP_TOP_UY = 98, /* gripTopUy: Float64, m, parameter */
  PERISTEP_VR_SPECIMEN_MODEL = 99, /* specimenModel: Enumeration, parameter */
  PERISTEP_VR_GRIP_LEFT_VX = 130, /* gripLeftVx: Float64, m/s, parameter */
  PERISTEP_VR_GRIP_LEFT_VY = 131, /* gripLeftVy: Float64, m/s, parameter */
  PERISTEP_VR_GRIP_RIGHT_VX = 132, /* gripRightVx: Float64, m/s, parameter */
  PERISTEP_VR_GRIP_RIGHT_VY = 133, /* gripRightVy: Float64, m/s, parameter */
  PERISTEP_VR_GRIP_BOTTOM_VX = 134, /* gripBottomVx: Float64, m/s, parameter */
  PERISTEP_VR_GRIP_BOTTOM_VY = 135, /* gripBottomVy: Float64, m/s, parameter */
  PERISTEP_VR_GRIP_TOP_VX = 136, /* gripTopVx: Float64, m/s, parameter */
  PERISTEP_VR_GRIP_TOP_VY = 137, /* gripTopVy: Float64, m/s, parameter */
  PERISTEP_VR_COLLAR_DUX_DX = 144, /* collarDuxDx: Float64, parameter */
  PERISTEP_VR_COLLAR_DUX_DY = 145, /* collarDuxDy: Float64, parameter */
  PERISTEP_VR_COLLAR_DUY_DX = 146, /* collarDuyDx: Float64, parameter */
  PERISTEP_VR_COLLAR_DUY_DY = 147, /* collarDuyDy: Float64, parameter */
  PERISTEP_VR_GRIP_BOX_X0 = 150, /* gripBoxX0: Float64[nGripBoxes], m, parameter */
  PERISTEP_VR_GRIP_BOX_Y0 = 151, /* gripBoxY0: Float64[nGripBoxes], m, parameter */
  PERISTEP_VR_GRIP_BOX_X1 = 152, /* gripBoxX1: Float64[nGripBoxes], m, parameter */
  PERISTEP_VR_GRIP_BOX_Y1 = 153, /* gripBoxY1: Float64[nGripBoxes], m, parameter */
  PERISTEP_VR_GRIP_BOX_HOLD = 154, /* gripBoxHold: Enumeration[nGripBoxes], parameter */
  PERISTEP_VR_GRIP_BOX_VX = 155, /* gripBoxVx: Float64[nGripBoxes], m/s, parameter */
  PERISTEP_VR_GRIP_BOX_VY = 156, /* gripBoxVy: Float64[nGripBoxes], m/s, parameter */
  PERISTEP_VR_BODY_FORCE_RATE_X = 157, /* bodyForceRateX: Float64[ny][nx], N/(m3.s), parameter */
  PERISTEP_VR_BODY_FORCE_RATE_Y = 158, /* bodyForceRateY: Float64[ny][nx], N/(m3.s), parameter */
  PERISTEP_VR_GLASS_YOUNGS_MODULUS = 70, /* glassYoungsModulus: Float64, Pa, parameter */
  PERISTEP_VR_CRYSTAL_YOUNGS_MODULUS = 71, /* crystalYoungsModulus: Float64, Pa, parameter */
  PERISTEP_VR_GLASS_FRACTURE_ENERGY = 72, /* glassFractureEnergy: Float64, J/m2, parameter */
  PERISTEP_VR_CRYSTAL_FRACTURE_ENERGY = 73, /* crystalFractureEnergy: Float64, J/m2, parameter */
  PERISTEP_VR_BULK_MODULUS = 74, /* bulkModulus: Float64, Pa, parameter */
  PERISTEP_VR_CRITICAL_ENERGY_RELEASE_RATE = 75, /* criticalEnergyReleaseRate: Float64, J/m2, parameter */
  PERISTEP_VR_DENSITY = 76, /* density: Float64, kg/m3, parameter */
  PERISTEP_VR_GAMUT_MATERIAL = 110, /* gamutMaterial: Enumeration, parameter */
  PERISTEP_VR_GAMUT_GRID = 111, /* gamutGrid: Enumeration, parameter */
  PERISTEP_VR_GAMUT_BONDS = 112, /* gamutBonds: UInt64, parameter */
  PERISTEP_VR_SCATTER_DENOMINATOR = 113, /* scatterDenominator: Float64, parameter */
  PERISTEP_VR_WEIBULL_SHAPE = 114, /* weibullShape: Float64, parameter */
  PERISTEP_VR_GAMUT_PROTOCOL = 115, /* gamutProtocol: Enumeration, parameter */
  PERISTEP_VR_BAR_STRESS = 120, /* barStress: Float64, Pa, output */
  PERISTEP_VR_BAR_STRAIN = 121, /* barStrain: Float64, output */
  PERISTEP_VR_CYCLIC_EXPONENT = 122, /* cyclicExponent: Float64, output */
  PERISTEP_VR_CYCLIC_COEFFICIENT = 123, /* cyclicCoefficient: Float64, Pa, output */
  PERISTEP_VR_LEARNED_SAMPLE = 140, /* learnedSample: Enumeration, parameter */
  PERISTEP_VR_LEARNED_CRITICAL_STRETCH = 141, /* learnedCriticalStretch: Float64, parameter */
  PERISTEP_VR_PREDICTION_ERROR_U = 142, /* predictionErrorDisplacement: Float64, output */
  PERISTEP_VR_PREDICTION_ERROR_DAMAGE = 143, /* predictionErrorDamage: Float64, output */
  PERISTEP_VR_STRAIN_XX = 170, /* strainXX: Float64, parameter */
  PERISTEP_VR_STRAIN_YY = 171, /* strainYY: Float64, parameter */
  PERISTEP_VR_STRAIN_XY = 172, /* strainXY: Float64, parameter */
  PERISTEP_VR_PATCH_ERROR = 173 /* patchError: Float64, output */
};

enum PeriStepScene {
  PERISTEP_SCENE_SMOOTH = 1, /* smooth */
  PERISTEP_SCENE_COMPOSITE = 2, /* composite */
  PERISTEP_SCENE_INTERFACE_CRACK = 3, /* interfaceCrack */
  PERISTEP_SCENE_GLASS_CERAMIC = 4, /* glassCeramic */
  PERISTEP_SCENE_PLEXIGLASS_CRACK = 5, /* plexiglassCrack */
  PERISTEP_SCENE_BENDING_ONE_NOTCH = 6, /* bendingOneNotch */
  PERISTEP_SCENE_BENDING_TWO_NOTCHES = 7, /* bendingTwoNotches */
  PERISTEP_SCENE_KL_PLATE = 8, /* klPlate */
  PERISTEP_SCENE_SPECIMEN = 9, /* specimen */
  PERISTEP_SCENE_GAMUT_BAR = 10, /* gamutBar */
  PERISTEP_SCENE_LEARNED_FRACTURE = 11, /* learnedFracture */
  PERISTEP_SCENE_PATCH_TEST = 12 /* patchTest */
};

enum PeriStepMaterialField {
  PERISTEP_MATERIAL_MAP = 1, /* map */
  PERISTEP_MATERIAL_KL_FIELD = 2, /* klField */
  PERISTEP_MATERIAL_GLASS_CERAMIC = 3 /* glassCeramic */
};

enum PeriStepExactSolution {
  PERISTEP_EXACT_NONE = 1, /* none */
  PERISTEP_EXACT_SMOOTH = 2, /* smooth */
  PERISTEP_EXACT_COMPOSITE = 3, /* composite */
  PERISTEP_EXACT_INTERFACE_CRACK = 4 /* interfaceCrack */
};

enum PeriStepSpecimenModel {
  PERISTEP_SPECIMEN_QUASI_STATIC = 1, /* quasiStatic */
  PERISTEP_SPECIMEN_DYNAMIC = 2, /* dynamic */
  PERISTEP_SPECIMEN_ELASTIC = 3 /* elastic */
};

enum PeriStepGrip {
  PERISTEP_GRIP_FREE = 1, /* free */
  PERISTEP_GRIP_HELD = 2, /* held */
  PERISTEP_GRIP_HELD_X = 3, /* heldX */
  PERISTEP_GRIP_HELD_Y = 4 /* heldY */
};

enum PeriStepLinearSolver {
  PERISTEP_LINEAR_SOLVER_UMFPACK = 1, /* umfpack */
  PERISTEP_LINEAR_SOLVER_UMFPACK_AMD = 2, /* umfpackAmd */
  PERISTEP_LINEAR_SOLVER_SPARSE_LU = 3, /* sparseLU */
  PERISTEP_LINEAR_SOLVER_BICGSTAB_ILUT = 4 /* bicgstabIlut */
};

enum PeriStepCovariance {
  PERISTEP_COVARIANCE_EXPONENTIAL = 1, /* exponential */
  PERISTEP_COVARIANCE_GAUSSIAN = 2 /* gaussian */
};

enum PeriStepFieldTransform {
  PERISTEP_FIELD_AFFINE = 1, /* affine */
  PERISTEP_FIELD_LOGNORMAL = 2 /* lognormal */
};

enum PeriStepTimeIntegrator {
  PERISTEP_INTEGRATOR_CENTRAL_DIFFERENCE = 1, /* centralDifference */
  PERISTEP_INTEGRATOR_ARKODE_ERK = 2, /* arkodeErk */
  PERISTEP_INTEGRATOR_CVODE_BDF = 3 /* cvodeBdf */
};

enum PeriStepGamutMaterial {
  PERISTEP_GAMUT_MATERIAL_1 = 1, /* material1 */
  PERISTEP_GAMUT_MATERIAL_2 = 2 /* material2 */
};

enum PeriStepGamutGrid {
  PERISTEP_GAMUT_GRID_UNIFORM = 1, /* uniform */
  PERISTEP_GAMUT_GRID_STOCHASTIC = 2 /* stochastic */
};

enum PeriStepGamutProtocol {
  PERISTEP_GAMUT_MONOTONIC = 1, /* monotonic */
  PERISTEP_GAMUT_CYCLIC = 2 /* cyclic */
};

enum PeriStepLearnedSample {
  PERISTEP_LEARNED_TRAINING = 1, /* training */
  PERISTEP_LEARNED_TEST = 2, /* test */
  PERISTEP_LEARNED_TRAINING_FINE = 3 /* trainingFine */
};

enum PeriStepXiDistribution {
  PERISTEP_XI_NORMAL = 0, /* normal */
  PERISTEP_XI_UNIFORM = 1, /* uniform */
  PERISTEP_XI_UNUSED = 2 /* unused */
};

#endif
