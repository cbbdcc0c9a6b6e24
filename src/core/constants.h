/* constants.h - the physical and mathematical constants of the library, each once, with its
 * source (included by core_private.h; never installed). */
#ifndef LX_CONSTANTS_H
#define LX_CONSTANTS_H

#define LX__PI 3.14159265358979323846 /* pi */
#define LX__DEG (LX__PI / 180.0)      /* radians per degree */

/* Maximum luminous efficacies (lm/W), CIE 015:2018 sec. 7.1 and CIE 018:2019: 683 lm/W at
 * 540 THz scaled to the observer's peak. */
#define LX__KM_2 683.002    /* photopic, CIE 1931 2 deg (V(lambda) = ybar) */
#define LX__KM_10 683.599   /* CIE 1964 10 deg */
#define LX__KM_SCOT 1700.06 /* scotopic K'm, CIE 018:2019 */

/* Radiation constants (CODATA 2018; c2 as CIE 015:2018 uses it for the Planckian locus). */
#define LX__C1L 1.191042972e-16  /* 2 h c^2, W m^2 / sr */
#define LX__C2 1.4388e-2         /* second radiation constant, m K (CIE 015:2018) */
#define LX__C2_NM_K 1.4388e7     /* the same in nm K */
#define LX__SIGMA 5.670374419e-8 /* Stefan-Boltzmann constant, W m^-2 K^-4 */

/* Photon counting (SI 2019 exact values: h, c, N_A). */
#define LX__H 6.62607015e-34  /* Planck constant, J s */
#define LX__C 299792458.0     /* speed of light in vacuum, m/s */
#define LX__NA 6.02214076e23  /* Avogadro constant, 1/mol */
/* umol of photons per joule at 1 nm: lambda_nm * LX__UMOL_PER_J_NM = lambda / (h c N_A) in umol/J */
#define LX__UMOL_PER_J_NM (1e-9 * 1e6 / (LX__H * LX__C * LX__NA))

#endif /* LX_CONSTANTS_H */
