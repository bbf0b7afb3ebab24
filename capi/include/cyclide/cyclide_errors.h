/* cyclide status codes. The numbers are frozen: a code is added, never
 * renumbered or reused. Ranges: 0 ok; 1-99 invalid input; 100-199
 * degenerate geometry; 200-299 numerical failure; 300-399 resources;
 * 400-499 misuse or unsupported. */
#ifndef CYCLIDE_ERRORS_H
#define CYCLIDE_ERRORS_H

enum cyc_status {
  CYC_OK = 0,

  CYC_E_NULL_ARGUMENT = 1,     /* a required pointer is NULL */
  CYC_E_INVALID_ARGUMENT = 2,  /* a value out of its documented range */
  CYC_E_NOT_FINITE = 3,        /* NaN, Inf, or |x| > 1e100 in the input */
  CYC_E_DEGREE_TOO_HIGH = 4,   /* degree above CYC_MAX_CURVE_DEGREE etc. */
  CYC_E_BAD_DOMAIN = 5,        /* parameter interval empty or reversed */

  CYC_E_DEPENDENT_PLANES = 100,  /* PRCS planes M, N, B (nearly) dependent */
  CYC_E_ZERO_TANGENT = 101,      /* a PRCS input curve has p'(u) = 0 */
  CYC_E_COLLINEAR_POINTS = 102,  /* PRRS: p1(u), p2(u), p3(u) collinear */
  CYC_E_DEGENERATE_CIRCLE_PARAMETER = 103, /* f(u,.) not Mobius at u */
  CYC_E_NOT_CANAL = 104,         /* canal-only query on a ringed surface */
  CYC_E_SINGULAR_POINT = 105,    /* normal undefined at this point */
  CYC_E_DEGENERATE_RINGED = 106, /* eq. (3): n . c' = 0 at u */
  CYC_E_PARALLEL_LINES = 107,    /* DCMC: two input lines are parallel */
  CYC_E_NO_COMMON_NORMAL = 108,  /* DCMC: line directions share no normal */
  CYC_E_RANK_DEFICIENT = 109,    /* a system has more freedom than expected */
  CYC_E_AT_INVERSION_CENTER = 110, /* a point at the inversion center */
  CYC_E_NOT_PARABOLIC = 111,       /* needs an irreducible parabolic (cubic) cyclide */
  CYC_E_EMPTY_REAL_LOCUS = 112,    /* the requested real circle/surface is empty */
  CYC_E_TOO_FEW_LINES = 113,       /* Props. 3/5: the cyclide lacks the needed lines */
  CYC_E_NO_NORMAL_FORM = 114,      /* Props. 2/8/9: input without a normal form */
  CYC_E_NOT_PYTHAGOREAN = 115,     /* seed 001: the data admit no P-curve */
  CYC_E_INTERSECTING_CIRCLES = 116, /* seed 001 §6: joining circles on the sphere meet */
  CYC_E_NESTED_SPHERES = 117,       /* seed 002: one sphere inside (or equal to) the other */
  CYC_E_CURVATURE_RADIUS_TOO_LARGE = 118, /* seed 002 Remark 2: kappa r >= 1 at an end */
  CYC_E_SPHERE_PENCIL = 119, /* seed 003 sec. 3.1 Case I: dim span(a1,a2,a3) = 2, a pencil of touching spheres (no envelope) */
  CYC_E_NO_TOUCHING_SPHERE = 120, /* seed 003 sec. 3.1 Case II.1: A = R^{1,2}, no Lie sphere touches all three */
  CYC_E_SINGLE_TOUCHING_SPHERE = 121, /* seed 003 sec. 3.1 Case II.2: A = R^{1,1,1}, exactly one sphere touches all three */
  CYC_E_DEGENERATE_CYCLIDE = 122, /* seed 003 sec. 3.3: A or its complement lies in e_r-perp (all spheres are points): a curve, not a surface */
  CYC_E_NOT_ISOMETRIC = 123, /* seed 003 Thm. 2.3: Gram matrices or signatures differ, no orthogonal map exists */
  CYC_E_NOT_ON_LIE_QUADRIC = 124, /* seed 003 (2): the vector is not neutral (not a Lie sphere) */
  CYC_E_POINT_AT_INFINITY = 125, /* seed 003 (26): the point sphere is n_inf (the point lies at infinity) */
  CYC_E_TANGENT_GENERATING_SPHERES = 126, /* seed 003 Lemma 4.6 (i): r0 . s0 = 0, the cones' generating spheres touch */
  CYC_E_BLEND_FOLDS = 127, /* seed 003 Alg. 2: a cyclide patch meets a glued circle from the wrong side (the blend folds back) */
  CYC_E_DEVELOPABLE = 128, /* seed 004 Thm. 3.2: the plane and its two partials are dependent (no envelope point: a developable) */
  CYC_E_POLE_IN_GAUSS_IMAGE = 129, /* seed 004 §4.2: a unit normal equals the projection centre W = (0,0,1) */
  CYC_E_RIDGE = 130, /* seed 004 Fig. 3: patches share tangent planes along an edge but meet in an edge of regression */

  CYC_E_NUMERICAL_OVERFLOW = 200, /* values beyond the supported range */

  CYC_E_BUFFER_TOO_SMALL = 300,  /* caller buffer capacity too small */
  CYC_E_OUT_OF_MEMORY = 301,     /* the allocator returned NULL */
  CYC_E_IO = 302,                /* a file could not be opened or written */

  CYC_E_UNSUPPORTED = 400,       /* feature not built (e.g. no Ceres) */
  CYC_E_INTERNAL = 401           /* a bug in cyclide: please report */
};

#endif
