/* unc_private.h - the measurement-uncertainty engine's internals (never installed): the counter-based
 * generator of the trials, the input model bound to one spectrum, its image in the space of the
 * integrals the quantities are computed from, the quantity providers (the colour layer adds its own),
 * the linear algebra, and the Monte Carlo and GUM drivers. README "Measurement uncertainty". */
#ifndef LX_UNC_PRIVATE_H
#define LX_UNC_PRIVATE_H

#include "spectral/spectral_private.h"

#include <stdint.h>

/* ---- the generator (unc_rng.c; kernels/unc_trials.cl is its twin) ---- */

/* Philox4x32-10 (Salmon, Moraes, Dror and Shaw 2011): out = the 10-round bijection of ctr under key. */
void lx__philox4x32(const uint32_t ctr[4], const uint32_t key[2], uint32_t out[4]);
/* Stream 0 holds the normal deviates of a trial, stream 1 its uniforms: block b of trial t is
 * philox(ctr = {t low, t high, b, stream}, key = {seed low, seed high}). */
#define LX__UNC_STREAM_NORMAL 0u
#define LX__UNC_STREAM_UNIFORM 1u
/* The four uniforms (0, 1) of a block: (w + 0.5) / 2^32. */
void lx__unc_uniform4(uint64_t seed, uint64_t trial, uint32_t block, double u[4]);
/* The four standard normal deviates of a block: Box-Muller on its uniforms (u0, u1), (u2, u3):
 * z0 = r cos(2 pi u1), z1 = r sin(2 pi u1), r = sqrt(-2 ln u0); |z| < 6.8. */
void lx__unc_normal4(uint64_t seed, uint64_t trial, uint32_t block, double z[4]);
/* The largest |z| the generator can give (its smallest uniform is 2^-33). */
#define LX__UNC_Z_MAX 6.8

/* ---- linear algebra (unc_linalg.c) ---- */

/* The eigenvalues of the symmetric n x n matrix a (row-major, not modified) into ev, ascending:
 * Householder tridiagonalisation and the implicit QL method. LX_ENOMEM without a message. */
lx_status lx__sym_eigenvalues(size_t n, const double *a, double *ev);
/* The pivoted Cholesky factor of the symmetric positive semi-definite n x n matrix a: g (n x
 * *rank, row-major with row length n, the caller's n x n) with a = g g^T, stopping when the largest
 * remaining diagonal element is below tol times the largest diagonal element of a. Returns the
 * smallest remaining diagonal element relative to that (negative when a is not semi-definite). */
double lx__pivoted_cholesky(size_t n, const double *a, double tol, double *g, size_t *rank);
/* The quantile of the standard normal distribution at p (0 < p < 1), to 1e-15. */
double lx__normal_quantile(double p);

/* ---- the input model (unc_model.c) ---- */

typedef struct lx__unc_comp {
    lx_unc_component c; /* arrays copied: lambda_nm, u, cov, label owned here */
} lx__unc_comp;

struct lx_unc_model {
    size_t count, cap;
    lx__unc_comp *comp;
    const lx_spd *column_of[8]; /* spectra of the set a SPEC's column= took its values from */
    size_t ncolumn;
};

/* One component bound to a spectrum: what it does to the sample values (unc_model.c). */
typedef struct lx__unc_bound {
    lx_unc_kind kind;
    double sigma;
    double *u2;     /* NOISE: n variances; COVARIANCE: n x n covariance (absolute) */
    double *vec;    /* SCALE, FOURIER: S; SHIFT: -dS/dlambda (the mean of the two slopes at each sample);
                     * BANDWIDTH: S'' (second divided differences, 0 at the ends) */
    double b0;      /* BANDWIDTH: nominal bandpass (nm) */
    int terms;      /* FOURIER: N (0: to be chosen) */
    const char *label;
} lx__unc_bound;

/* Binds every component of m to spd (checks the grids of per-wavelength components, turns
 * relative values into absolute ones): *out an array of m->count (free with lx__unc_unbind).
 * Errors: LX_EINVAL naming the component (a grid that is not the spectrum's, a negative or
 * non-finite uncertainty, a covariance that is not symmetric positive semi-definite). */
lx_status lx__unc_bind(lx_ctx *ctx, const lx_unc_model *m, const lx_spd *spd, lx__unc_bound **out);
void lx__unc_unbind(lx__unc_bound *b, size_t count);
/* The value of the piecewise-linear spectrum at x, its end values held beyond its ends (the
 * spectrum read through a shifted wavelength scale). */
double lx__unc_shifted(const lx_spd *spd, double x, size_t *hint);

/* ---- providers: the quantities and the integrals they are computed from ---- */

/* A family of quantities that are functions of linear integrals of the spectrum. */
typedef struct lx__unc_provider {
    int nint;           /* integrals */
    int nout;           /* quantities */
    const int *out_q;   /* lx_unc_quantity of each quantity */
    /* its integrals as weights on spd's grid (nint x spd->n, row-major) */
    lx_status (*rows)(lx_ctx *ctx, void *self, const lx_spd *spd, double *A);
    /* the quantities y (m rows of nout, row length ldy) of m sets of integrals L (row length ldl);
     * NaN where a quantity is undefined. ctx: the calling thread's own; scratch from scratch_new. */
    void (*eval)(lx_ctx *ctx, void *self, void *scratch, size_t m, const double *L, size_t ldl, double *y, size_t ldy);
    /* the Jacobian dy/dL at L (nout x nint), analytic; NULL: central differences of eval.
     * Returns 0 where it cannot (the caller differences). */
    int (*jacobian)(lx_ctx *ctx, void *self, const double *L, double *J);
    void *(*scratch_new)(void *self); /* NULL: no scratch */
    void (*scratch_free)(void *self, void *scratch);
    void *self;
} lx__unc_provider;

/* The spectral layer's providers (unc_colorimetry.c): colorimetry (X ... radiant), alpha-opic
 * (irradiances, EDI, DER), PAR, for observer obs and integration method. *p is filled; self
 * points into state, which the caller keeps (lx__unc_spectral_state). */
typedef struct lx__unc_spectral_state {
    lx_observer obs;
    lx_method method;
    double par_ok[3]; /* 1 when the spectrum covers the PAR band (LX_COVERAGE_MIN), else 0 */
} lx__unc_spectral_state;
void lx__unc_colorimetry_provider(lx__unc_spectral_state *s, lx__unc_provider *p);
void lx__unc_alphaopic_provider(lx__unc_spectral_state *s, lx__unc_provider *p);
void lx__unc_par_provider(lx__unc_spectral_state *s, lx__unc_provider *p);

/* ---- the model in the space of the integrals (unc_space.c) ---- */

typedef struct lx__unc_fourier {
    double sigma;
    int terms;        /* N */
    double *F;        /* (2 N + 1) x K: A S, then A (S sqrt2 sin 2 pi i x), A (S sqrt2 cos 2 pi i x), i = 1..N */
} lx__unc_fourier;

/* A component's covariance of the integrals as F^T F: m rows of K (GUM sums (J . row)^2, which
 * keeps a zero sensitivity zero to rounding). */
typedef struct lx__unc_factor {
    size_t m;
    double *F;
} lx__unc_factor;

typedef struct lx__unc_space {
    size_t n, K;        /* samples, integrals */
    double *A;          /* K x n: the integrals' weights */
    double *L0;         /* K: the integrals of the measured spectrum */
    size_t ncomp;
    lx__unc_factor *fac; /* per component: its covariance of the integrals, factored */
    int *gauss;         /* per component: 1 when it is a normal, linear one (in the factor G) */
    /* Monte Carlo */
    size_t r;           /* rank of the normal part */
    double *G;          /* its factor, column by column: r x K (L = L0 + sum_j z_j G[j]) */
    double shift_sigma; /* all shifts together (0: none) */
    size_t nshift;      /* breakpoints of the shift table (0: evaluated per trial) */
    double *shift_d;    /* nshift breakpoints (nm), increasing */
    double *shift_T;    /* nshift x K: L(d) - L0 */
    const lx_spd *spd;  /* for shifts evaluated per trial */
    size_t nbw;
    double *bw_sigma, *bw_b0, *bw_D; /* per bandwidth component; D: nbw x K (A S'') */
    size_t nfourier;
    lx__unc_fourier *fourier;
    size_t nnormal, nuniform; /* draws per trial */
} lx__unc_space;

/* Builds the space of spd under the bound model b (ncomp components): K integrals from the
 * providers' rows, every component's covariance of them (Fourier's in lx__unc_space_finish, once
 * its N is known: terms 0 leaves room for lx__unc_fourier_auto_max()). On failure the caller
 * still frees sp. */
lx_status lx__unc_space_make(lx_ctx *ctx, const lx_spd *spd, const lx__unc_bound *b, size_t ncomp,
                             const lx__unc_provider *prov, size_t nprov, lx__unc_space *sp);
int lx__unc_fourier_auto_max(void);
/* After every Fourier component's terms are set: their factors, and the draws per trial (LX_ENOMEM
 * without a message). */
lx_status lx__unc_space_finish(lx__unc_space *sp, const lx__unc_bound *b);
void lx__unc_space_free(lx__unc_space *sp);

/* ---- trials (unc_trials.c: the CPU twin; OpenCL: kernels/unc_trials.cl) ---- */

/* The integrals of trials t0 .. t0 + m - 1 into L (m x K): L0 plus each component's draw. */
void lx__unc_trials_cpu(const lx__unc_space *sp, uint64_t seed, uint64_t t0, size_t m, double *L);
/* The integrals of `count` trials from t0 drawn on an OpenCL device when the backend rule picks it
 * (lx__backend_choose with `asked`): *L (count x K, malloc'ed) and *used OPENCL; else *L NULL and
 * *used CPU (the caller draws them on the CPU, lx__unc_trials_cpu). */
lx_status lx__unc_trials_device(lx_ctx *ctx, const lx__unc_space *sp, uint64_t seed, uint64_t t0, size_t count,
                                lx_backend asked, double **L, lx_backend *used);

/* ---- the run (unc_run.c) ---- */

/* The group (LX_UNC_*) of quantity q. */
unsigned lx__unc_group(int q);
/* lx_spd_uncertainty with the providers of every quantity (the colorimetry provider among them:
 * the Fourier model's N is chosen by its CCT); only the groups opts->quantities asks for are
 * reported. At most 16 providers. */
lx_status lx__unc_run(lx_ctx *ctx, const lx_spd *spd, const lx_unc_model *m, const lx_unc_opts *opts,
                      const lx__unc_provider *prov, size_t nprov, lx_unc_result **out);

#endif /* LX_UNC_PRIVATE_H */
