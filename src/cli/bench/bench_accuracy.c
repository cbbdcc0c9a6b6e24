/* bench_accuracy.c - `luxcalc bench accuracy`: each method's error against an independent reference
 * and its time, on the same inputs, as markdown tables and one error-against-time PNG per topic:
 * spectra (here), radiance fields and lighting (bench_accuracy_fields.c). */
#include "cli/cli.h"
#include "bench_accuracy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>


/* Seconds per call of fn(arg): repetitions grow until one run lasts >= 3 ms (at most `cap`
 * calls), then the median of 5 runs. Every call does the same work on the same input. */
double acc_time(void (*fn)(void *), void *arg, long cap)
{
    long reps = 1;
    double t = 0;
    for (;;) {
        double t0 = cli_bench_now_s();
        for (long r = 0; r < reps; r++) fn(arg);
        t = cli_bench_now_s() - t0;
        if (t >= 3e-3 || reps >= cap) break;
        reps = t > 0 ? (long)fmin((double)cap, fmax(2.0 * reps, reps * 4e-3 / t)) : reps * 8;
    }
    double ts[5];
    for (int k = 0; k < 5; k++) {
        double t0 = cli_bench_now_s();
        for (long r = 0; r < reps; r++) fn(arg);
        ts[k] = (cli_bench_now_s() - t0) / (double)reps;
    }
    return cli_bench_median(ts, 5);
}

void acc_fmt_time(char *buf, size_t n, double s)
{
    if (s < 1e-6) snprintf(buf, n, "%.3g ns", s * 1e9);
    else if (s < 1e-3) snprintf(buf, n, "%.3g us", s * 1e6);
    else if (s < 1) snprintf(buf, n, "%.3g ms", s * 1e3);
    else snprintf(buf, n, "%.3g s", s);
}

void acc_fmt_err(char *buf, size_t n, double e)
{
    if (isnan(e)) snprintf(buf, n, "-");
    else if (e == 0) snprintf(buf, n, "0");
    else snprintf(buf, n, "%.2e", e);
}

/* ------------------------------------------------------------------------------------------ */
/* Spectra                                                                                     */
/* ------------------------------------------------------------------------------------------ */

#define NCASE 6
#define PBRT_MAX 60

typedef struct scase {
    const char *name, *kind;
    lx_spd native;           /* the data as a user has it (views or owned arrays below) */
    double *own_l, *own_v;   /* owned samples (lines, blackbody) */
    double T_K;              /* blackbody: > 0 (every grid is sampled from Planck's law) */
    double ref[3];           /* reference X, Y, Z (integrals without Km) */
    const char *ref_how;
} scase;

static lx_spd cmf[3];

static double xyz_int(lx_ctx *ctx, const lx_spd *s, lx_method m, double out[3])
{
    for (int k = 0; k < 3; k++)
        if (lx_spd_integrate(ctx, s, &cmf[k], m, &out[k])) return -1;
    return 0;
}

/* Linear interpolation of a piecewise-linear spectrum, 0 outside. */
static double pwl(const lx_spd *s, double l)
{
    if (l < s->lambda_nm[0] || l > s->lambda_nm[s->n - 1]) return 0;
    size_t lo = 0, hi = s->n - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (s->lambda_nm[mid] <= l) lo = mid;
        else hi = mid;
    }
    double t = (l - s->lambda_nm[lo]) / (s->lambda_nm[hi] - s->lambda_nm[lo]);
    return s->value[lo] + t * (s->value[hi] - s->value[lo]);
}

/* The case's spectrum on the uniform grid start + k step within [360, 830] and its own range:
 * sampled from the piecewise-linear data (for 5 nm tables and steps that are multiples of 5,
 * exactly every step/5-th row), or from Planck's law for the blackbody. */
static size_t grid_of(const scase *c, double step, double **lam, double **val)
{
    int table = c->own_l == NULL && !(c->T_K > 0); /* a CIE table: its own range; lines and Planck: 360-830 (zero outside) */
    double lo = fmax(360, table ? c->native.lambda_nm[0] : 360);
    double hi = fmin(830, table ? c->native.lambda_nm[c->native.n - 1] : 830);
    lo = ceil(lo / step - 1e-9) * step;
    size_t n = (size_t)floor((hi - lo) / step + 1e-9) + 1;
    *lam = malloc(n * sizeof **lam);
    *val = malloc(n * sizeof **val);
    for (size_t k = 0; k < n; k++) {
        double l = lo + (double)k * step;
        (*lam)[k] = l;
        (*val)[k] = c->T_K > 0 ? lx_planck(l, c->T_K) : pwl(&c->native, l);
    }
    return n;
}

/* pbrt's AverageSpectrumSamples: the average of the piecewise-linear samples over [l0, l1],
 * constant beyond the first and last sample (pbrt-v3 src/core/spectrum.cpp). */
static double pbrt_average(const lx_spd *s, double l0, double l1)
{
    const double *L = s->lambda_nm, *V = s->value;
    size_t n = s->n;
    if (l1 <= L[0]) return V[0];
    if (l0 >= L[n - 1]) return V[n - 1];
    double sum = 0;
    if (l0 < L[0]) sum += V[0] * (L[0] - l0);
    if (l1 > L[n - 1]) sum += V[n - 1] * (l1 - L[n - 1]);
    size_t i = 0;
    while (l0 > L[i + 1]) i++;
    for (; i + 1 < n && l1 >= L[i]; i++) {
        double a = fmax(l0, L[i]), b = fmin(l1, L[i + 1]);
        if (b <= a) continue;
        double va = V[i] + (V[i + 1] - V[i]) * (a - L[i]) / (L[i + 1] - L[i]);
        double vb = V[i] + (V[i + 1] - V[i]) * (b - L[i]) / (L[i + 1] - L[i]);
        sum += 0.5 * (va + vb) * (b - a);
    }
    return sum / (l1 - l0);
}

typedef struct pbrt_job {
    const lx_spd *s;
    int nb;
    double cbar[3][PBRT_MAX]; /* the CMFs averaged into the bins (pbrt's SampledSpectrum::Init) */
    double xyz[3];
} pbrt_job;

static void pbrt_init(pbrt_job *j, int nb)
{
    j->nb = nb;
    for (int i = 0; i < nb; i++)
        for (int k = 0; k < 3; k++) j->cbar[k][i] = pbrt_average(&cmf[k], 400 + 300.0 * i / nb, 400 + 300.0 * (i + 1) / nb);
}

/* FromSampled (bin averages of the SPD) then ToXYZ: sum of cbar c times the bin width. */
static void pbrt_run(void *arg)
{
    pbrt_job *j = arg;
    double c[PBRT_MAX];
    for (int i = 0; i < j->nb; i++) c[i] = pbrt_average(j->s, 400 + 300.0 * i / j->nb, 400 + 300.0 * (i + 1) / j->nb);
    for (int k = 0; k < 3; k++) {
        double s = 0;
        for (int i = 0; i < j->nb; i++) s += j->cbar[k][i] * c[i];
        j->xyz[k] = s * 300.0 / j->nb;
    }
}

typedef struct int_job {
    lx_ctx *ctx;
    const lx_spd *s;
    lx_method m;
    double xyz[3];
} int_job;

static void int_run(void *arg)
{
    int_job *j = arg;
    xyz_int(j->ctx, j->s, j->m, j->xyz);
}

typedef struct batch_job {
    lx_ctx *ctx;
    lx_batch bt;
    lx_backend be;
    int kahan;
    double *out;
    int ok;
} batch_job;

static void batch_run(void *arg)
{
    batch_job *j = arg;
    static const lx_function F[3] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2};
    lx_batch_opts o = {.backend = j->be};
    if (j->kahan) setenv("LX_CL_ACCUM", "kahan", 1);
    j->ok = lx_batch_integrate(j->ctx, &j->bt, F, 3, &o, j->out) == LX_OK;
    if (j->kahan) unsetenv("LX_CL_ACCUM");
}

/* Errors of xyz against the case's reference: |dY|/Y, |dxy|, |dCCT| (NaN where CCT is undefined). */
static void errors(lx_ctx *ctx, const scase *c, const double xyz[3], double e[3])
{
    const double *r = c->ref;
    double sr = r[0] + r[1] + r[2], s = xyz[0] + xyz[1] + xyz[2];
    e[0] = fabs(xyz[1] / r[1] - 1);
    e[1] = s > 0 ? hypot(xyz[0] / s - r[0] / sr, xyz[1] / s - r[1] / sr) : NAN;
    double t0, d0, t1, d1;
    e[2] = NAN;
    if (lx_cct_from_xy(ctx, LX_OBSERVER_2, r[0] / sr, r[1] / sr, &t0, &d0) == LX_OK && fabs(d0) <= 0.05 && s > 0 &&
        lx_cct_from_xy(ctx, LX_OBSERVER_2, xyz[0] / s, xyz[1] / s, &t1, &d1) == LX_OK)
        e[2] = fabs(t1 - t0);
}

/* A triangular line: centre, half-base w, area a; appended as 3 samples (0, 2a/(2w)... , 0). */
static void add_line(double *l, double *v, size_t *n, double centre, double w, double area)
{
    l[*n] = centre - w, v[(*n)++] = 0;
    l[*n] = centre, v[(*n)++] = area / w;
    l[*n] = centre + w, v[(*n)++] = 0;
}

/* Analytic integral of a triangle line (centre c, half-base w, area a) against a CMF that is
 * linear between its 1 nm rows: a cmf(c) when the support lies inside one row interval; when c
 * is a row and the slopes left and right differ, a cmf(c) + (a/w)(s_r - s_l) w^2 / 6 (integrate
 * (1 - t/w)(a/w) t (s_r or -s_l) over t in [0, w] on each side). */
static double line_integral(const lx_spd *f, double c, double w, double a)
{
    double r = c - f->lambda_nm[0];
    size_t k = (size_t)floor(r);
    double fc = pwl(f, c);
    if (fabs(r - nearbyint(r)) < 1e-12) {
        k = (size_t)nearbyint(r);
        double sl = f->value[k] - f->value[k - 1], sr = f->value[k + 1] - f->value[k];
        return a * fc + (a / w) * (sr - sl) * w * w / 6;
    }
    (void)k; /* support inside [row k, row k + 1] (checked by the caller's choice of w) */
    return a * fc;
}

static void rgb_from_xyz(double M[3][3], const double xyz[3], double rgb[3])
{
    for (int i = 0; i < 3; i++) rgb[i] = M[i][0] * xyz[0] + M[i][1] * xyz[1] + M[i][2] * xyz[2];
}

/* The linear sRGB -> XYZ matrix (IEC 61966-2-1) and its inverse, computed (adjugate / determinant)
 * so that XYZ -> RGB -> XYZ is the identity to rounding. */
static void srgb_matrices(double M[3][3], double Mi[3][3])
{
    static const double S[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
    memcpy(M, S, sizeof S);
    double det = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            Mi[j][i] = S[i1][j1] * S[i2][j2] - S[i1][j2] * S[i2][j1];
        }
    for (int j = 0; j < 3; j++) det += S[0][j] * Mi[j][0];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) Mi[i][j] /= det;
}

/* The six spectra and their references: the CIE tables D65, FL2, HP1 (exact on the table), a 532
 * nm laser line and the Na D doublet (analytic), a 1000 K blackbody sampled every 5 nm (Planck at
 * 0.01 nm, exact). Loads the CMFs first. A CLI exit code. */
static int make_cases(lx_ctx *ctx, scase cs[NCASE])
{
    for (int k = 0; k < 3; k++)
        if (lx_function_get(ctx, (lx_function)(LX_FN_XBAR_2 + k), &cmf[k])) return cli_fail("bench", ctx, LX_EINVAL);
    memset(cs, 0, NCASE * sizeof *cs);
    const char *tab[3] = {"D65", "FL2", "HP1"}, *kinds[3] = {"smooth", "spiky", "spiky"};
    for (int i = 0; i < 3; i++) {
        cs[i].name = tab[i];
        cs[i].kind = kinds[i];
        if (lx_illuminant_get(ctx, tab[i], &cs[i].native)) return cli_fail("bench", ctx, LX_EINVAL);
        xyz_int(ctx, &cs[i].native, LX_METHOD_EXACT, cs[i].ref);
        cs[i].ref_how = "exact on the table";
    }
    /* 532 nm laser: a triangle of half-base 0.05 nm (FWHM 0.05 nm) and area 1, centred on a table row */
    scase *L = &cs[3];
    L->name = "laser 532";
    L->kind = "line";
    L->own_l = malloc(8 * sizeof(double));
    L->own_v = malloc(8 * sizeof(double));
    size_t nl = 0;
    add_line(L->own_l, L->own_v, &nl, 532.0, 0.05, 1.0);
    L->native = (lx_spd){"laser", nl, L->own_l, L->own_v};
    for (int k = 0; k < 3; k++) L->ref[k] = line_integral(&cmf[k], 532.0, 0.05, 1.0);
    L->ref_how = "analytic";
    /* Na D doublet: D2 588.995 nm and D1 589.592 nm (NIST Atomic Spectra Database, Na I, air
     * wavelengths), intensity 2 : 1 (the D2 : D1 line-strength ratio), half-base 0.004 nm: each
     * line lies between two table rows, so its integral is area x cmf(centre) exactly. */
    scase *N = &cs[4];
    N->name = "Na doublet";
    N->kind = "line";
    N->own_l = malloc(8 * sizeof(double));
    N->own_v = malloc(8 * sizeof(double));
    nl = 0;
    add_line(N->own_l, N->own_v, &nl, 588.995, 0.004, 2.0);
    add_line(N->own_l, N->own_v, &nl, 589.592, 0.004, 1.0);
    N->native = (lx_spd){"Na", nl, N->own_l, N->own_v};
    for (int k = 0; k < 3; k++) N->ref[k] = line_integral(&cmf[k], 588.995, 0.004, 2.0) + line_integral(&cmf[k], 589.592, 0.004, 1.0);
    N->ref_how = "analytic";
    /* 1000 K blackbody: the data a user has is Planck's law sampled every 5 nm; the truth is
     * Planck's law every 0.01 nm integrated exactly against the CMFs (interpolation error ~1e-9) */
    scase *B = &cs[5];
    B->name = "blackbody 1000 K";
    B->kind = "steep";
    B->T_K = 1000;
    {
        double *l, *v;
        size_t n = grid_of(B, 0.01, &l, &v);
        lx_spd fine = {"bb", n, l, v};
        xyz_int(ctx, &fine, LX_METHOD_EXACT, B->ref);
        free(l);
        free(v);
        n = grid_of(B, 5, &B->own_l, &B->own_v);
        B->native = (lx_spd){"bb", n, B->own_l, B->own_v};
    }
    B->ref_how = "Planck 0.01 nm, exact";
    return CLI_OK;
}

/* ---- the methods ---- */
enum { NM = 14, NB = 2000 };
static const char *mname[NM] = {"exact (native data)", "linear1nm (native data)", "cie15 1 nm", "cie15 5 nm",
                                "cie15 10 nm", "cie15 20 nm", "pbrt-v3 60 bins (5 nm)", "pbrt 30 bins (10 nm)",
                                "batch CPU double", "batch CPU float", "batch OpenCL double", "batch OpenCL float",
                                "batch OpenCL float, Kahan float sums", "RGB (3 coefficients)"};
static const char *mlabel[NM] = {"exact", "linear1nm", "cie15 1 nm", "cie15 5 nm", "cie15 10 nm", "cie15 20 nm", "pbrt 60 bins",
                                 "pbrt 30 bins", "batch CPU f64", "batch CPU f32", "batch CL f64", "batch CL f32", "CL f32 Kahan", "RGB"};

/* Every method's errors and time on every case (NaN: not run), and whether OpenCL ran. */
typedef struct {
    double err[NM][NCASE][3], tm[NM][NCASE], vs_cpu[NM][NCASE];
    int have_cl;
} spec_res;

/* Case c on the batch kernels (rows 8..12): its 1 nm grid 360-830 (471 samples) repeated NB
 * times, CPU double and float, OpenCL double, float and float with Kahan sums (r->have_cl
 * cleared when OpenCL fails). */
static void batch_methods(lx_ctx *ctx, const scase *C, int c, spec_res *r)
{
    double *l, *v;
    size_t n = grid_of(C, 1, &l, &v);
    double *vd = calloc((size_t)NB * 471, sizeof *vd);
    float *vf = calloc((size_t)NB * 471, sizeof *vf);
    double *out = malloc((size_t)NB * 3 * sizeof *out), cpu[3] = {0, 0, 0};
    size_t j0 = (size_t)nearbyint(l[0] - 360);
    for (size_t i = 0; i < NB; i++)
        for (size_t j = 0; j < n; j++) vd[i * 471 + j0 + j] = v[j], vf[i * 471 + j0 + j] = (float)v[j];
    for (int b = 0; b < 5; b++) {
        batch_job bj = {ctx, {.n_spectra = NB, .n_lambda = 471, .start_nm = 360, .step_nm = 1}, LX_BACKEND_CPU, 0, out, 0};
        bj.bt.dtype = (b == 0 || b == 2) ? LX_F64 : LX_F32;
        bj.bt.values = bj.bt.dtype == LX_F64 ? (const void *)vd : (const void *)vf;
        bj.be = b < 2 ? LX_BACKEND_CPU : LX_BACKEND_OPENCL;
        bj.kahan = b == 4;
        if (b >= 2 && !r->have_cl) continue;
        batch_run(&bj);
        if (!bj.ok) {
            if (b >= 2) r->have_cl = 0;
            continue;
        }
        double t = acc_time(batch_run, &bj, 50) / NB;
        double worst = 0;
        for (size_t i = 0; i < NB; i++)
            for (int k = 0; k < 3; k++) {
                double d = fabs(out[i * 3 + k] - out[k]);
                if (d > worst) worst = d;
            }
        if (b == 0) memcpy(cpu, out, sizeof cpu);
        r->tm[8 + b][c] = t;
        errors(ctx, C, out, r->err[8 + b][c]);
        double dv = 0;
        for (int k = 0; k < 3; k++) dv = fmax(dv, fabs(out[k] - cpu[k]) / fmax(fabs(cpu[1]), 1e-300));
        r->vs_cpu[8 + b][c] = fmax(dv, worst / fmax(fabs(cpu[1]), 1e-300));
    }
    free(l);
    free(v);
    free(vd);
    free(vf);
    free(out);
}

/* Case c on every method: exact and linear1nm on the native data, cie15 on 1..20 nm grids, pbrt's
 * bins, the batch kernels, and the RGB light (linear sRGB from the reference XYZ, and back). */
static void run_methods(lx_ctx *ctx, const scase *C, int c, spec_res *r)
{
    double xyz[3];
    int_job ij = {ctx, &C->native, LX_METHOD_EXACT, {0}};
    r->tm[0][c] = acc_time(int_run, &ij, 100000);
    errors(ctx, C, ij.xyz, r->err[0][c]);
    ij.m = LX_METHOD_LINEAR1NM;
    r->tm[1][c] = acc_time(int_run, &ij, 100000);
    errors(ctx, C, ij.xyz, r->err[1][c]);
    static const double steps[4] = {1, 5, 10, 20};
    for (int s = 0; s < 4; s++) {
        double *l, *v;
        size_t n = grid_of(C, steps[s], &l, &v);
        lx_spd g = {"grid", n, l, v};
        int_job gj = {ctx, &g, LX_METHOD_CIE15, {0}};
        r->tm[2 + s][c] = acc_time(int_run, &gj, 100000);
        errors(ctx, C, gj.xyz, r->err[2 + s][c]);
        free(l);
        free(v);
    }
    for (int p = 0; p < 2; p++) {
        pbrt_job pj;
        pbrt_init(&pj, p ? 30 : 60);
        pj.s = &C->native;
        r->tm[6 + p][c] = acc_time(pbrt_run, &pj, 100000);
        errors(ctx, C, pj.xyz, r->err[6 + p][c]);
    }
    batch_methods(ctx, C, c, r);
    /* the RGB light: linear sRGB from the reference XYZ, and back: lossless for the light itself */
    double rgb[3], M[3][3], Mi[3][3];
    srgb_matrices(M, Mi);
    rgb_from_xyz(Mi, C->ref, rgb);
    rgb_from_xyz(M, rgb, xyz);
    errors(ctx, C, xyz, r->err[13][c]);
    r->tm[13][c] = NAN;
}

/* The table of error e (0 |dY|/Y with the float-vs-double column, 1 |dxy|, 2 |dCCT| on the cases
 * where CCT is defined) for every method. */
static void error_table(FILE *o, const scase *cs, const spec_res *r, int e)
{
    static const char *ename[3] = {"|dY|/Y", "|dxy| (CIE 1931 xy)", "|dCCT| in K (where CCT is defined: |Duv| <= 0.05)"};
    fprintf(o, "%s:\n\n| method | time |", ename[e]);
    for (int c = 0; c < NCASE; c++)
        if (e < 2 || !isnan(r->err[0][c][2]) || c == 0) fprintf(o, " %s |", cs[c].name);
    fprintf(o, "%s\n|---|---|", e == 0 ? " float vs CPU double (worst, rel. to Y) |" : "");
    for (int c = 0; c < NCASE; c++)
        if (e < 2 || !isnan(r->err[0][c][2]) || c == 0) fprintf(o, "---|");
    fprintf(o, "%s\n", e == 0 ? "---|" : "");
    for (int m = 0; m < NM; m++) {
        double ts[NCASE];
        int nt = 0;
        for (int c = 0; c < NCASE; c++)
            if (!isnan(r->tm[m][c])) ts[nt++] = r->tm[m][c];
        if (m >= 10 && m <= 12 && !r->have_cl) continue;
        char tb[32], eb[32];
        if (nt) acc_fmt_time(tb, sizeof tb, cli_bench_median(ts, nt));
        else snprintf(tb, sizeof tb, "-");
        fprintf(o, "| %s | %s |", mname[m], tb);
        for (int c = 0; c < NCASE; c++) {
            if (!(e < 2 || !isnan(r->err[0][c][2]) || c == 0)) continue;
            acc_fmt_err(eb, sizeof eb, r->err[m][c][e]);
            fprintf(o, " %s |", eb);
        }
        if (e == 0) {
            double w = 0;
            int any = 0;
            for (int c = 0; c < NCASE; c++)
                if (!isnan(r->vs_cpu[m][c])) w = fmax(w, r->vs_cpu[m][c]), any = 1;
            acc_fmt_err(eb, sizeof eb, any ? w : NAN);
            fprintf(o, " %s |", eb);
        }
        fprintf(o, "\n");
    }
    fprintf(o, "\n");
}

/* The section's header, what it measures against which references, and its three error tables. */
static void spectra_tables(FILE *o, lx_ctx *ctx, const scase *cs, const spec_res *r)
{
    fprintf(o, "## bench accuracy: spectra\n\n");
    fprintf(o, "Spectra: D65 (smooth), FL2 and HP1 (spiky; CIE tables at 5 nm), a 532 nm laser line (FWHM 0.05 nm), "
               "the Na D doublet (588.995 and 589.592 nm, 2 : 1), a 1000 K blackbody (steep; the data is Planck's law at 5 nm). "
               "CIE 1931 2 deg observer. References: the exact method on the native table data for the CIE illuminants "
               "(the published samples are the definition of the illuminant, and their piecewise-linear interpolant integrated "
               "exactly against the piecewise-linear CMFs adds no discretisation of its own); the closed-form integral of each "
               "triangle line against the linearly interpolated CMFs for the lines; Planck's law at 0.01 nm integrated "
               "exactly for the blackbody. `cie15 S nm` sums the data sampled every S nm (5 nm tables: every S/5-th row); "
               "pbrt averages the SPD and the CMFs over equal bins between 400 and 700 nm (pbrt-v3 `SampledSpectrum`: "
               "`nSpectralSamples = 60`, 5 nm bins; and 30 bins of 10 nm, pbrt-v2's `nSpectralSamples = 30`); "
               "batch rows run `lx_batch_integrate` (cie15 rule, 1 nm grid, %d copies; time per spectrum). "
               "Time: median of 5 runs per spectrum (X, Y, Z), median over the spectra.\n\n", NB);
    for (int e = 0; e < 3; e++) error_table(o, cs, r, e);
    if (!r->have_cl) fprintf(o, "OpenCL rows left out: no OpenCL device (%s).\n\n", lx_ctx_errmsg(ctx));
}

/* A surface's linear sRGB: its colour under D65 (d65, whose XYZ is yd65), scaled so that the white
 * of D65 is (1, 1, 1). */
static void surface_rgb(lx_ctx *ctx, const lx_spd *tcs, const lx_spd *d65, double Mi[3][3], const double yd65[3],
                        double srgb[3])
{
    double refl_xyz[3], wrgb[3];
    size_t n = tcs->n;
    double *v = malloc(n * sizeof *v);
    for (size_t k = 0; k < n; k++) v[k] = tcs->value[k] * pwl(d65, tcs->lambda_nm[k]);
    lx_spd p = {"p", n, tcs->lambda_nm, v};
    xyz_int(ctx, &p, LX_METHOD_EXACT, refl_xyz);
    free(v);
    rgb_from_xyz(Mi, refl_xyz, srgb);
    rgb_from_xyz(Mi, yd65, wrgb);
    for (int k = 0; k < 3; k++) srgb[k] /= wrgb[k];
}

/* The XYZ of light x surface, exact on the union of their wavelengths inside both ranges (0 when
 * fewer than 2). */
static void product_truth(lx_ctx *ctx, const lx_spd *light, const lx_spd *tcs, double truth[3])
{
    size_t cap = light->n + tcs->n, n = 0;
    double *ul = malloc(cap * sizeof *ul), *uv = malloc(cap * sizeof *uv);
    double lo = fmax(light->lambda_nm[0], tcs->lambda_nm[0]), hi = fmin(light->lambda_nm[light->n - 1], tcs->lambda_nm[tcs->n - 1]);
    size_t a = 0, b = 0;
    while (a < light->n || b < tcs->n) {
        double x = b >= tcs->n || (a < light->n && light->lambda_nm[a] <= tcs->lambda_nm[b]) ? light->lambda_nm[a] : tcs->lambda_nm[b];
        if (a < light->n && light->lambda_nm[a] == x) a++;
        if (b < tcs->n && tcs->lambda_nm[b] == x) b++;
        if (x < lo || x > hi) continue;
        ul[n] = x;
        uv[n++] = pwl(light, x) * pwl(tcs, x);
    }
    truth[0] = truth[1] = truth[2] = 0;
    if (n >= 2) {
        lx_spd p = {"p", n, ul, uv};
        xyz_int(ctx, &p, LX_METHOD_EXACT, truth);
    }
    free(ul);
    free(uv);
}

/* One row: case C's light reflected by surface tcs (number ti, linear sRGB srgb): the RGB product
 * and pbrt's 60 bins against the spectral product. */
static void reflect_row(FILE *o, lx_ctx *ctx, const scase *C, const lx_spd *tcs, int ti, const double srgb[3], double M[3][3],
                        double Mi[3][3])
{
    const lx_spd *light = &C->native;
    double *fl = NULL, *fv = NULL;
    lx_spd fine;
    if (C->T_K > 0) { /* the blackbody's truth: Planck at 0.01 nm */
        size_t n = grid_of(C, 0.01, &fl, &fv);
        fine = (lx_spd){"bb", n, fl, fv};
        light = &fine;
    }
    double truth[3], rgb_l[3], rx[3], prod[3];
    product_truth(ctx, light, tcs, truth);
    rgb_from_xyz(Mi, C->ref, rgb_l);
    for (int k = 0; k < 3; k++) prod[k] = rgb_l[k] * srgb[k];
    rgb_from_xyz(M, prod, rx);
    /* pbrt: bin averages of light and surface, multiplied */
    pbrt_job pl;
    pbrt_init(&pl, 60);
    double cl[PBRT_MAX], cs2[PBRT_MAX], px[3] = {0, 0, 0};
    for (int i = 0; i < 60; i++) {
        cl[i] = pbrt_average(&C->native, 400 + 5.0 * i, 405 + 5.0 * i);
        cs2[i] = pbrt_average(tcs, 400 + 5.0 * i, 405 + 5.0 * i);
        for (int k = 0; k < 3; k++) px[k] += pl.cbar[k][i] * cl[i] * cs2[i] * 5.0;
    }
    scase tmp = *C;
    memcpy(tmp.ref, truth, sizeof truth);
    double e1[3], e2[3];
    errors(ctx, &tmp, rx, e1);
    errors(ctx, &tmp, px, e2);
    char b1[32], b2[32], b3[32], b4[32];
    acc_fmt_err(b1, sizeof b1, e1[0]);
    acc_fmt_err(b2, sizeof b2, e1[1]);
    acc_fmt_err(b3, sizeof b3, e2[0]);
    acc_fmt_err(b4, sizeof b4, e2[1]);
    fprintf(o, "| %s | TCS%02d | %s | %s | %s | %s |\n", C->name, ti, b1, b2, b3, b4);
    free(fl);
    free(fv);
}

/* Where the RGB light fails: the light reflected by saturated test colour samples (TCS09, TCS12). */
static int rgb_surfaces(lx_ctx *ctx, FILE *o, const scase *cs)
{
    double M[3][3], Mi[3][3];
    srgb_matrices(M, Mi);
    static const int tcs_i[2] = {9, 12};
    lx_spd d65;
    lx_illuminant_get(ctx, "D65", &d65);
    fprintf(o, "The RGB light is lossless for the light itself (XYZ -> linear sRGB -> XYZ), so its rows above are 0. "
               "Its error shows in the light reflected by coloured surfaces: the reflectance as linear sRGB (its colour "
               "under D65, white -> (1, 1, 1), as textures are authored), light RGB x surface RGB, against the spectral "
               "product (light x reflectance on the union of their samples, exact method). pbrt 60 bins beside it "
               "(product of bin averages).\n\n");
    fprintf(o, "| light | surface | RGB \\|dY\\|/Y | RGB \\|dxy\\| | pbrt-v3 60 bins \\|dY\\|/Y | pbrt-v3 \\|dxy\\| |\n|---|---|---|---|---|---|\n");
    double yd65[3];
    xyz_int(ctx, &d65, LX_METHOD_EXACT, yd65);
    for (int t = 0; t < 2; t++) {
        lx_spd tcs;
        if (lx_tcs_get(ctx, tcs_i[t], &tcs)) return cli_fail("bench", ctx, LX_EINVAL);
        double srgb[3];
        surface_rgb(ctx, &tcs, &d65, Mi, yd65, srgb);
        for (int c = 0; c < NCASE; c++) reflect_row(o, ctx, &cs[c], &tcs, tcs_i[t], srgb, M, Mi);
    }
    fprintf(o, "\n");
    return CLI_OK;
}

/* The plot: worst |dY|/Y over the continuous spectra and over the lines, against the median time. */
static int spectra_png(lx_ctx *ctx, FILE *o, const char *png, const spec_res *r)
{
    lx_plot_point pts[2 * NM];
    int np = 0;
    for (int g = 0; g < 2; g++)
        for (int m = 0; m < NM; m++) {
            double ts[NCASE], w = 0;
            int nt = 0;
            for (int c = 0; c < NCASE; c++) {
                if (!isnan(r->tm[m][c])) ts[nt++] = r->tm[m][c];
                int is_line = c == 3 || c == 4;
                if (is_line == g && !isnan(r->err[m][c][0])) w = fmax(w, r->err[m][c][0]);
            }
            if (!nt) continue;
            pts[np++] = (lx_plot_point){cli_bench_median(ts, nt), w, mlabel[m], g};
        }
    static const char *series[2] = {"D65, FL2, HP1, 1000 K", "laser, Na doublet"};
    if (lx_error_time_write_png(ctx, png, "Spectra: worst relative error in Y", "time per spectrum (s), median",
                                "|\u0394Y| / Y", (size_t)np, pts, 2, series))
        return cli_fail("bench", ctx, LX_EIO);
    fprintf(o, "Plot: worst |dY|/Y over D65, FL2, HP1 and the blackbody, and over the two line spectra, against the "
               "median time per spectrum.\n\n");
    return CLI_OK;
}

int acc_spectra(lx_ctx *ctx, FILE *o, const char *png)
{
    scase cs[NCASE];
    int rc = make_cases(ctx, cs);
    if (rc) return rc;
    spec_res r;
    for (int m = 0; m < NM; m++)
        for (int c = 0; c < NCASE; c++) {
            r.err[m][c][0] = r.err[m][c][1] = r.err[m][c][2] = NAN;
            r.tm[m][c] = r.vs_cpu[m][c] = NAN;
        }
    r.have_cl = 1;
    for (int c = 0; c < NCASE; c++) run_methods(ctx, &cs[c], c, &r);
    spectra_tables(o, ctx, cs, &r);
    if ((rc = rgb_surfaces(ctx, o, cs))) return rc;
    if (png && (rc = spectra_png(ctx, o, png, &r))) return rc;
    for (int c = 0; c < NCASE; c++) {
        free(cs[c].own_l);
        free(cs[c].own_v);
    }
    return CLI_OK;
}

/* ------------------------------------------------------------------------------------------ */
/* The topic: markdown on out; with -o FILE the PNGs go beside FILE (FILE's stem + _spectra.png...) */
/* ------------------------------------------------------------------------------------------ */

int cli_bench_accuracy(FILE *out, const char *outpath)
{
    char base[1024] = "", p1[1100], p2[1100], p3[1100], p4[1100];
    if (outpath && strcmp(outpath, "-")) {
        snprintf(base, sizeof base, "%s", outpath);
        char *dot = strrchr(base, '.'), *slash = strrchr(base, '/');
        if (dot && (!slash || dot > slash)) *dot = 0;
        snprintf(p1, sizeof p1, "%s_spectra.png", base);
        snprintf(p2, sizeof p2, "%s_radiance.png", base);
        snprintf(p3, sizeof p3, "%s_lighting.png", base);
        snprintf(p4, sizeof p4, "%s_nearfield.png", base);
    }
    lx_ctx *ctx = cli_ctx("bench");
    if (!ctx) return CLI_RUNTIME;
    double t0 = cli_bench_now_s();
    fprintf(out, "# bench accuracy: error against time\n\n");
    int rc = acc_spectra(ctx, out, *base ? p1 : NULL);
    if (!rc) rc = acc_radiance(ctx, out, *base ? p2 : NULL);
    if (!rc) rc = acc_lighting(ctx, out, *base ? p3 : NULL);
    if (!rc) rc = acc_nearfield(ctx, out, *base ? p4 : NULL);
    if (!rc) {
        if (*base) {
            const char *s1 = strrchr(p1, '/'), *s2 = strrchr(p2, '/'), *s3 = strrchr(p3, '/'), *s4 = strrchr(p4, '/');
            fprintf(out, "Plots: ![spectra](%s) ![radiance](%s) ![lighting](%s) ![near field](%s)\n\n", s1 ? s1 + 1 : p1,
                    s2 ? s2 + 1 : p2, s3 ? s3 + 1 : p3, s4 ? s4 + 1 : p4);
        } else {
            fprintf(out, "(PNG plots are written with -o DIR/NAME.md, as DIR/NAME_spectra.png, _radiance.png, _lighting.png, _nearfield.png.)\n\n");
        }
        fprintf(out, "bench accuracy: %.1f s in all.\n\n", cli_bench_now_s() - t0);
    }
    lx_ctx_destroy(ctx);
    return rc;
}
