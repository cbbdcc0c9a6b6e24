/* grid.c - illuminance on points from placed luminaires: E = I(C, gamma) cos(xi) / d^2 summed over
 * luminaires, with the exact model (bilinear or smooth interpolation, the luminous area integrated to a
 * tolerance where the point model's estimated error asks for it, nearfield.c) and the fast path: a
 * table indexed by sqrt(1 - |cos g|) and the diamond angle of C (no acos/atan2), run by threads on
 * the CPU or by kernels/grid.cl. */
#include "grid_private.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


/* Break-even of LX_BACKEND_AUTO in point-luminaire pairs: estimates (no GPU has been measured;
 * a CPU-type OpenCL device is never chosen by auto). Cold includes starting OpenCL and building
 * the program (0.3-1 s); warm only the buffers and the transfer of the points. */
#define LX_GRID_CL_COLD 1e9
#define LX_GRID_CL_WARM 1e8

/* ---- planes and statistics ---- */

lx_status lx_plane_axis(lx_ctx *ctx, char axis, double level_m, double a0, double a1, double b0, double b1, double spacing_m,
                        size_t na, size_t nb, lx_plane *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_plane_axis: NULL argument");
    if (!isfinite(level_m) || !isfinite(a0) || !isfinite(a1) || !isfinite(b0) || !isfinite(b1) || a1 < a0 || b1 < b0)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the area must be finite with A0 <= A1 and B0 <= B1");
    lx_plane p;
    memset(&p, 0, sizeof p);
    switch (axis) {
    case 'z': p.origin_m[2] = level_m; p.u[0] = 1; p.v[1] = 1; p.normal[2] = 1; break;
    case 'x': p.origin_m[0] = level_m; p.u[1] = 1; p.v[2] = 1; p.normal[0] = 1; break;
    case 'y': p.origin_m[1] = level_m; p.u[0] = 1; p.v[2] = 1; p.normal[1] = 1; break;
    default: return lx__error(ctx, LX_EINVAL, NULL, 0, "the plane axis must be x, y or z (got '%c')", axis);
    }
    if (spacing_m > 0) {
        double fa = floor((a1 - a0) / spacing_m + 1e-9) + 1, fb = floor((b1 - b0) / spacing_m + 1e-9) + 1;
        if (fa * fb > 1e9) return lx__error(ctx, LX_EINVAL, NULL, 0, "the spacing gives more than 1e9 points");
        na = (size_t)fa;
        nb = (size_t)fb;
        a1 = a0 + (double)(na - 1) * spacing_m;
        b1 = b0 + (double)(nb - 1) * spacing_m;
    } else if (na < 1 || nb < 1 || (double)na * (double)nb > 1e9) {
        return lx__error(ctx, LX_EINVAL, NULL, 0, "give a positive spacing or 1 to 1e9 points");
    }
    p.a0 = a0;
    p.a1 = a1;
    p.b0 = b0;
    p.b1 = b1;
    p.na = na;
    p.nb = nb;
    *out = p;
    return LX_OK;
}

lx_status lx_plane_points(lx_ctx *ctx, const lx_plane *p, double **points, size_t *n)
{
    LX__NEED_CTX(ctx);
    if (!p || !points || !n) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_plane_points: NULL argument");
    *points = NULL;
    if (p->na < 1 || p->nb < 1) return lx__error(ctx, LX_EINVAL, NULL, 0, "a plane needs at least 1 x 1 points");
    size_t cnt = p->na * p->nb;
    double *v = lx__alloc_n(cnt * 3, sizeof *v);
    if (!v) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for %zu points", cnt);
    for (size_t j = 0; j < p->nb; j++) {
        double b = p->nb > 1 ? p->b0 + (p->b1 - p->b0) * (double)j / (double)(p->nb - 1) : p->b0;
        for (size_t i = 0; i < p->na; i++) {
            double a = p->na > 1 ? p->a0 + (p->a1 - p->a0) * (double)i / (double)(p->na - 1) : p->a0;
            double *q = v + 3 * (j * p->na + i);
            for (int k = 0; k < 3; k++) q[k] = p->origin_m[k] + a * p->u[k] + b * p->v[k];
        }
    }
    *points = v;
    *n = cnt;
    return LX_OK;
}

void lx_plane_points_free(double *points) { lx__free(points); }

lx_status lx_grid_stats_compute(lx_ctx *ctx, const double *E, size_t n, lx_grid_stats *out)
{
    LX__NEED_CTX(ctx);
    if (!E || !out || n == 0) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_grid_stats_compute: no values");
    double sum = 0, c = 0, mn = E[0], mx = E[0];
    for (size_t i = 0; i < n; i++) { /* Neumaier summation */
        double t = sum + E[i];
        c += fabs(sum) >= fabs(E[i]) ? (sum - t) + E[i] : (E[i] - t) + sum;
        sum = t;
        if (E[i] < mn) mn = E[i];
        if (E[i] > mx) mx = E[i];
    }
    lx_grid_stats r = {0}; /* reserved included (ABI policy) */
    r.avg = (sum + c) / (double)n;
    if (!isfinite(r.avg) && isfinite(mn) && isfinite(mx)) {
        /* values near the top of the double range: the sum again of E / 2^e (exact), then back */
        int e = 0;
        frexp(fmax(fabs(mn), fabs(mx)), &e);
        e += 64; /* room for 2^64 values */
        sum = c = 0;
        for (size_t i = 0; i < n; i++) {
            double v = ldexp(E[i], -e), t = sum + v;
            c += fabs(sum) >= fabs(v) ? (sum - t) + v : (v - t) + sum;
            sum = t;
        }
        r.avg = ldexp((sum + c) / (double)n, e);
    }
    r.min = mn;
    r.max = mx;
    r.u0 = r.avg > 0 ? mn / r.avg : NAN;
    *out = r;
    return LX_OK;
}

/* ---- placed luminaires ---- */

/* The luminaire's frame in world coordinates: ex (C0), ey (C90), ez (up, -aim). */
static void frame(const lx_placement *pl, double ex[3], double ey[3], double ez[3])
{
    double a[3] = {pl->aim[0], pl->aim[1], pl->aim[2]};
    double r = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (int k = 0; k < 3; k++) a[k] /= r;
    /* the rotation taking the nadir n = (0,0,-1) to a: Rodrigues, R = I + [v]x + [v]x^2 / (1 + c) */
    double R[3][3];
    double c = -a[2];
    if (c < -1 + 1e-12) { /* straight up: half turn about x */
        double H[3][3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
        memcpy(R, H, sizeof R);
    } else {
        double v[3] = {a[1], -a[0], 0}; /* n x a with n = (0, 0, -1) */
        double K[3][3] = {{0, -v[2], v[1]}, {v[2], 0, -v[0]}, {-v[1], v[0], 0}};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double k2 = 0;
                for (int m = 0; m < 3; m++) k2 += K[i][m] * K[m][j];
                R[i][j] = (i == j) + K[i][j] + k2 / (1 + c);
            }
    }
    double cr = cos(pl->rotate_rad), sr = sin(pl->rotate_rad);
    for (int i = 0; i < 3; i++) {
        double x = R[i][0], y = R[i][1];
        ex[i] = cr * x + sr * y;
        ey[i] = -sr * x + cr * y;
        ez[i] = R[i][2];
    }
}

typedef lx__plum plum;

/* ---- the cosine-indexed table ---- */

/* Row r of hemisphere h (0: below, u = cos g >= 0) is at sqrt(1 - |u|) = r / ns; column k at
 * diamond angle 4 k / cols. Values: the bilinear model in that direction. */
static void table_dir(int h, int r, int ns, int k, int nq, double d[3])
{
    double s = (double)r / ns, one_u = s * s, au = 1 - one_u; /* |cos g| */
    double st = sqrt(one_u * (2 - one_u));                    /* sin g = sqrt(1 - u^2) */
    double cx = 1, cy = 0;
    if (nq > 0) {
        double p = (double)k / nq, q = p - floor(p);
        int quad = (int)floor(p) & 3;
        double x = 1 - q, y = q, n = sqrt(x * x + y * y);
        x /= n;
        y /= n;
        switch (quad) {
        case 0: cx = x; cy = y; break;
        case 1: cx = -y; cy = x; break;
        case 2: cx = -x; cy = -y; break;
        default: cx = y; cy = -x; break;
        }
    }
    d[0] = st * cx;
    d[1] = st * cy;
    d[2] = h == 0 ? -au : au;
}

static float *build_table(const lx_luminaire *lum, int ns, int nq, int *cols, const double **pair)
{
    int axial = lum->photometric_type == 1 && lum->n_c == 1;
    if (axial) nq = 0;
    int nc = nq > 0 ? 4 * nq + 1 : 1;
    /* an axial table's pairs follow its floats at the next 16-byte offset */
    size_t rows = 2 * (size_t)(ns + 1), at = (rows * sizeof(float) + 15) / 16 * 16;
    float *t = lx__alloc(nc == 1 ? at + 2 * rows * sizeof(double) : rows * (size_t)nc * sizeof *t);
    if (!t) return NULL;
    for (int h = 0; h < 2; h++)
        for (int r = 0; r <= ns; r++)
            for (int k = 0; k < nc; k++) {
                double d[3];
                table_dir(h, r, ns, k, nq, d);
                t[((size_t)h * (ns + 1) + r) * nc + k] = (float)lx_luminaire_intensity_dir(lum, LX_INTERP_BILINEAR, d[0], d[1], d[2]);
            }
    *pair = NULL;
    if (nc == 1) { /* the pairs of an axial table: the value and the step to the next row, as lx__table_eval forms them */
        double *pr = (double *)(void *)((char *)t + at);
        for (size_t r = 0; r < rows; r++) {
            pr[2 * r] = t[r];
            pr[2 * r + 1] = r + 1 < rows ? (double)(t[r + 1] - t[r]) : 0;
        }
        *pair = pr;
    }
    *cols = nc;
    return t;
}

/* One pair, point model, exact interpolation or table. n: receiver normal. */
static inline double pair_point(const plum *p, lx_interp interp, const double *pt, const double *n)
{
    double w[3] = {pt[0] - p->pos[0], pt[1] - p->pos[1], pt[2] - p->pos[2]};
    double d2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    if (!(d2 > 0)) return 0;
    double d = sqrt(d2);
    double cx = -(w[0] * n[0] + w[1] * n[1] + w[2] * n[2]);
    if (cx <= 0) return 0;
    double x = w[0] * p->ex[0] + w[1] * p->ex[1] + w[2] * p->ex[2];
    double y = w[0] * p->ey[0] + w[1] * p->ey[1] + w[2] * p->ey[2];
    double z = w[0] * p->ez[0] + w[1] * p->ez[1] + w[2] * p->ez[2];
    double I = interp == LX_INTERP_TABLE ? lx__table_eval(p, x, y, z, d) : lx_luminaire_intensity_dir(p->lum, interp, x, y, z);
    return p->scale * I * cx / (d2 * d);
}

/* ---- near field: the luminous area as converged sums of point sources ---- */

size_t lx__area_cells(int circular, int n)
{
    return circular ? 2 * (size_t)n * (size_t)n : (size_t)n * (size_t)n;
}

void lx__area_cell(int circular, double w, double l, int n, size_t c, double *a, double *b)
{
    if (circular) { /* ring i of n (equal areas: midpoint in r^2), sector j of 2n */
        size_t i = c / (2 * (size_t)n), j = c % (2 * (size_t)n);
        double r = 0.5 * w * sqrt((i + 0.5) / n), ph = LX__PI * (j + 0.5) / n;
        *a = r * cos(ph);
        *b = r * sin(ph);
    } else {
        size_t i = c / (size_t)n, j = c % (size_t)n;
        *a = w * ((i + 0.5) / n - 0.5);
        *b = l * ((j + 0.5) / n - 0.5);
    }
}

double lx__area_refine(double (*mean)(void *arg, int n), void *arg, int circular, double tol, int n_max,
                       unsigned long long *cells, int *converged)
{
    double prev = mean(arg, 2), xprev = prev, x = prev, dprev = INFINITY;
    unsigned long long cnt = lx__area_cells(circular, 2);
    int ok = 0;
    for (int n = 4; n <= n_max; n *= 2) {
        double e = mean(arg, n);
        cnt += lx__area_cells(circular, n);
        x = (4 * e - prev) / 3; /* the midpoint rule's error is even in the cell size */
        double dx = fabs(x - xprev);
        /* converged: this step's change and a quarter of the step before's within tol (the change
         * alone can vanish by chance where the intensity is bilinear: kinks at the table's
         * angles leave the extrapolated sums an O(h^2) remainder that oscillates with h) */
        if (n >= 8 && fmax(dx, 0.25 * dprev) <= tol * fabs(x)) {
            ok = 1;
            break;
        }
        dprev = isnan(dx) ? INFINITY : dx;
        xprev = x;
        prev = e;
    }
    if (cells) *cells += cnt;
    if (converged) *converged = ok;
    return x;
}

typedef struct near_arg {
    const plum *p;
    lx_interp interp;
    const double *pt, *n;
} near_arg;

/* The mean over the n-level cells of the point-source illuminance of each cell (its share of the
 * intensity from its own position). */
static double near_mean(void *arg, int n)
{
    const near_arg *A = arg;
    const plum *p = A->p;
    plum sub = *p;
    size_t cells = lx__area_cells(p->circular, n);
    double sum = 0;
    for (size_t c = 0; c < cells; c++) {
        double a, b;
        lx__area_cell(p->circular, p->w, p->l, n, c, &a, &b);
        for (int m = 0; m < 3; m++) sub.pos[m] = p->pos[m] + a * p->ex[m] + b * p->ey[m];
        sum += pair_point(&sub, A->interp, A->pt, A->n);
    }
    return sum / (double)cells;
}

/* Near field: the luminous area subdivided (2, 4, 8, ... cells per side, up to LX__NEAR_MAX) until
 * the Richardson-extrapolated illuminance changes by less than tol relative. */
#define LX__NEAR_MAX LX__NEAR_MAX_CELLS
static double pair_near(const plum *p, lx_interp interp, const double *pt, const double *n, double tol,
                        unsigned long long *cells, unsigned long long *unconverged)
{
    near_arg A = {p, interp == LX_INTERP_TABLE ? LX_INTERP_BILINEAR : interp, pt, n};
    int ok = 0;
    double x = lx__area_refine(near_mean, &A, p->circular, tol, LX__NEAR_MAX, cells, &ok);
    if (!ok) ++*unconverged;
    return x > 0 ? x : 0;
}

/* ---- the computation ---- */

typedef struct job {
    const plum *pl;
    size_t m;
    const double *pts, *nrm;
    int shared;
    size_t i0, i1;
    lx_interp interp;
    lx_model model;
    double tol;          /* near-field tolerance */
    int simd;            /* lx__grid_simd() */
    double *E;
    const size_t *area;  /* the luminaires with an opening (n_area of them) */
    size_t n_area;
    lx__nf_probe *pr;    /* scratch, n_area each: probes, decisions, order */
    unsigned char *nf;
    size_t *ord;
    unsigned long long near_pairs, near_cells, near_unconverged, probes; /* OUT */
} job;

typedef struct probe_arg {
    const plum *p;
    lx_interp interp;
    const double *pt, *n;
} probe_arg;

/* The point model of the whole luminaire moved to offset (a, b) on its opening. */
static double probe_g(void *arg, double a, double b)
{
    const probe_arg *A = arg;
    plum sub = *A->p;
    for (int k = 0; k < 3; k++) sub.pos[k] = A->p->pos[k] + a * A->p->ex[k] + b * A->p->ey[k];
    return pair_point(&sub, A->interp, A->pt, A->n);
}

/* The near-field pass of one point. *e holds the point model of every luminaire (through the
 * table or the exact interpolation, as j->interp); each pair with an opening is decided (AUTO:
 * from the probes of its point-model error against the tolerance, lx__nf_decide; AREA: always
 * integrated) and the integrated ones replace their point terms. */
static void near_pass(job *j, const double *pt, const double *n, double *e)
{
    lx_interp exact = j->interp == LX_INTERP_TABLE ? LX_INTERP_BILINEAR : j->interp;
    size_t k = j->n_area;
    if (j->model == LX_MODEL_AREA) {
        for (size_t a = 0; a < k; a++) j->nf[a] = 1;
    } else {
        for (size_t a = 0; a < k; a++) {
            const plum *p = &j->pl[j->area[a]];
            probe_arg A = {p, exact, pt, n};
            double w0 = pt[0] - p->pos[0], w1 = pt[1] - p->pos[1], w2 = pt[2] - p->pos[2];
            lx__nf_probe_pair(probe_g, &A, p->circular, p->w, p->l, sqrt(w0 * w0 + w1 * w1 + w2 * w2),
                              lx__nf_faces(p->pos, p->ex, p->ey, p->circular, p->w, p->l, pt, n), &j->pr[a]);
        }
        j->probes += k;
        lx__nf_decide(k, j->pr, *e, j->tol, j->nf, j->ord);
    }
    for (size_t a = 0; a < k; a++) {
        if (!j->nf[a]) continue;
        const plum *p = &j->pl[j->area[a]];
        double P = j->model != LX_MODEL_AREA && j->interp != LX_INTERP_TABLE ? j->pr[a].point
                                                                              : pair_point(p, j->interp, pt, n);
        *e += pair_near(p, j->interp, pt, n, j->tol, &j->near_cells, &j->near_unconverged) - P;
        j->near_pairs++;
    }
}

#define BLK 256 /* points per block of the table path: 7 arrays of BLK doubles stay in L1 */

/* The table path: blocks of points, each luminaire's transform applied to a whole block
 * (lx__grid_table_block, the SIMD loops), then the near-field pass per point. */
static void run_table_job(job *j)
{
    double X[BLK], Y[BLK], Z[BLK], NX[BLK], NY[BLK], NZ[BLK], acc[BLK];
    if (j->shared) {
        NX[0] = j->nrm[0];
        NY[0] = j->nrm[1];
        NZ[0] = j->nrm[2];
    }
    for (size_t b0 = j->i0; b0 < j->i1; b0 += BLK) {
        size_t nb = j->i1 - b0 < BLK ? j->i1 - b0 : BLK;
        const double *P = j->pts + 3 * b0;
        for (size_t i = 0; i < nb; i++) {
            X[i] = P[3 * i];
            Y[i] = P[3 * i + 1];
            Z[i] = P[3 * i + 2];
            acc[i] = 0;
        }
        if (!j->shared)
            for (size_t i = 0; i < nb; i++) {
                NX[i] = j->nrm[3 * (b0 + i)];
                NY[i] = j->nrm[3 * (b0 + i) + 1];
                NZ[i] = j->nrm[3 * (b0 + i) + 2];
            }
        for (size_t m = 0; m < j->m; m++) lx__grid_table_block(&j->pl[m], nb, X, Y, Z, NX, NY, NZ, j->shared, j->simd, acc);
        if (j->model != LX_MODEL_POINT && j->n_area)
            for (size_t i = 0; i < nb; i++) near_pass(j, P + 3 * i, j->shared ? j->nrm : j->nrm + 3 * (b0 + i), &acc[i]);
        memcpy(j->E + b0, acc, nb * sizeof *acc);
    }
}

static void run_job(void *arg, int t)
{
    job *j = (job *)arg + t;
    if (j->interp == LX_INTERP_TABLE) {
        run_table_job(j);
        return;
    }
    for (size_t i = j->i0; i < j->i1; i++) {
        const double *pt = j->pts + 3 * i, *n = j->shared ? j->nrm : j->nrm + 3 * i;
        double e = 0;
        for (size_t m = 0; m < j->m; m++) e += pair_point(&j->pl[m], j->interp, pt, n);
        if (j->model != LX_MODEL_POINT && j->n_area) near_pass(j, pt, n, &e);
        j->E[i] = e;
    }
}

/* The near-field pass over points [i0, i1) whose point model is already in E (the OpenCL path). */
static void run_near_job(void *arg, int t)
{
    job *j = (job *)arg + t;
    for (size_t i = j->i0; i < j->i1; i++)
        near_pass(j, j->pts + 3 * i, j->shared ? j->nrm : j->nrm + 3 * i, &j->E[i]);
}

/* Runs fn over n points on up to 64 threads, each with its job and its scratch; adds the work
 * to the context's counters. near_only: run_near_job (E holds the point model already). */
static lx_status run_jobs(lx_ctx *ctx, const plum *pl, size_t m, const double *pts, size_t n, const double *nrm, int shared,
                          lx_interp interp, lx_model model, double tol, int threads, int near_only, double *E)
{
    int T = lx__threads(threads, (long)(n / 256 + 1));
    job jobs[64];
    size_t n_area = 0;
    for (size_t k = 0; k < m; k++) n_area += pl[k].size_m > 0;
    size_t *area = lx__alloc_n(n_area ? n_area : 1, sizeof *area);
    size_t per = n_area ? n_area : 1;
    lx__nf_probe *pr = lx__alloc_n((size_t)T * per, sizeof *pr);
    unsigned char *nf = lx__alloc((size_t)T * per);
    size_t *ord = lx__alloc_n((size_t)T * per, sizeof *ord);
    if (!area || !pr || !nf || !ord) {
        lx__free(area), lx__free(pr), lx__free(nf), lx__free(ord);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t k = 0, a = 0; k < m; k++)
        if (pl[k].size_m > 0) area[a++] = k;
    int simd = lx__grid_simd();
    for (int t = 0; t < T; t++)
        jobs[t] = (job){pl, m, pts, nrm, shared, n * (size_t)t / (size_t)T, n * (size_t)(t + 1) / (size_t)T, interp, model,
                        tol, simd, E, area, n_area, pr + (size_t)t * per, nf + (size_t)t * per, ord + (size_t)t * per,
                        0, 0, 0, 0};
    void (*fn)(void *, int) = near_only ? run_near_job : run_job;
    int ran = lx__parallel_run(T, fn, jobs);
    for (int t = ran; t < T; t++) fn(jobs, t); /* the threads that did not start */
    unsigned long long unconv = 0, pairs = 0, probes = 0;
    for (int t = 0; t < T; t++) {
        ctx->counters.nearfield_pairs += jobs[t].near_pairs;
        ctx->counters.nearfield_subdivisions += jobs[t].near_cells;
        ctx->counters.nearfield_probes += jobs[t].probes;
        unconv += jobs[t].near_unconverged;
        pairs += jobs[t].near_pairs;
        probes += jobs[t].probes;
    }
    if (model != LX_MODEL_POINT && n_area)
        lx__log(ctx, LX_LOG_INFO, "grid: %llu of %llu pairs with a luminous opening integrated over it (%s)", pairs,
                (unsigned long long)n * n_area,
                model == LX_MODEL_AREA ? "model area" : "the others' estimated point-model error is within the tolerance");
    (void)probes;
    if (unconv)
        lx__log(ctx, LX_LOG_INFO, "grid: %llu near-field pairs did not reach the tolerance %g at %d cells per side", unconv,
                tol, LX__NEAR_MAX);
    lx__free(area), lx__free(pr), lx__free(nf), lx__free(ord);
    return LX_OK;
}

#if LX_OPENCL
lx_status lx__grid_opencl(lx_ctx *ctx, const plum *pl, size_t m, const float *tables, size_t tables_n,
                          const double *pts, size_t n, const double *nrm, int shared, int fp32, double *E);
#endif

/* Checks the options and the normals; gives the maintenance factor and the near-field tolerance
 * (their defaults where 0). */
static lx_status grid_check_opts(lx_ctx *ctx, const lx_grid_opts *o, const double *normals, size_t n, int shared_normal,
                                 double *mf_out, double *tol_out)
{
    lx_status st = lx__check_reserved(ctx, "grid options", o->reserved, sizeof o->reserved);
    if (st) return st;
    double mf = o->maintenance_factor == 0 ? 1 : o->maintenance_factor;
    if (!(mf > 0) || mf > 1)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the maintenance factor must be in (0, 1] (got %g)", mf);
    if (o->interp != LX_INTERP_BILINEAR && o->interp != LX_INTERP_SMOOTH && o->interp != LX_INTERP_TABLE)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown interpolation %d", (int)o->interp);
    if (o->model != LX_MODEL_AUTO && o->model != LX_MODEL_POINT && o->model != LX_MODEL_AREA)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "grids use the auto, point or area model");
    if (o->table_n < 0 || o->table_n == 1 || o->table_n > LX__GRID_MAX_TABLE_ROWS)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "table rows must be 2 to %d (got %d; 0: 1024)",
                         LX__GRID_MAX_TABLE_ROWS, o->table_n);
    double tol = o->nearfield_tol == 0 ? LX__NEARFIELD_TOL : o->nearfield_tol;
    if (!(tol >= 1e-12) || !(tol <= 0.1))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the near-field tolerance must be in [1e-12, 0.1] (got %g)", tol);
    lx_backend backend = o->backend == LX_BACKEND_AUTO ? lx_backend_from_env() : o->backend;
    if (backend == LX_BACKEND_OPENCL && o->interp != LX_INTERP_TABLE)
        return lx__error(ctx, LX_EINVAL, NULL, 0,
                         "the OpenCL backend computes the table interpolation only (interp table)");
    for (size_t i = 0; i < (shared_normal ? 1 : n); i++) {
        const double *q = normals + 3 * i;
        double r = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        if (!(fabs(r - 1) < 1e-6))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "receiver normal %zu is not a unit vector", i);
    }
    *mf_out = mf;
    *tol_out = tol;
    return LX_OK;
}

/* The prepared luminaires: frame, scale (maintenance factor and TILT), opening and, for the table
 * interpolation, their intensity tables (one per distinct luminaire, owned through own[]; tables_n
 * counts the floats of them all). */
static lx_status grid_place(lx_ctx *ctx, const lx_placement *lums, size_t m, const lx_grid_opts *o, double mf, plum *pl,
                            float **own, size_t *tables_n)
{
    int ns = o->table_n > 0 ? o->table_n : 1024, nq = 90;
    for (size_t i = 0; i < m; i++) {
        const lx_placement *p = &lums[i];
        if (!p->lum || !p->lum->full_cd)
            return lx__error(ctx, LX_EINVAL, NULL, 0, "luminaire %zu has no photometry", i + 1);
        double r = sqrt(p->aim[0] * p->aim[0] + p->aim[1] * p->aim[1] + p->aim[2] * p->aim[2]);
        if (!(r > 0) || !isfinite(r) || !isfinite(p->pos_m[0] + p->pos_m[1] + p->pos_m[2]) || !isfinite(p->rotate_rad))
            return lx__error(ctx, LX_EINVAL, NULL, 0,
                             "luminaire %zu: position, aim and rotation must be finite, aim non-zero", i + 1);
        plum *q = &pl[i];
        q->lum = p->lum;
        memcpy(q->pos, p->pos_m, sizeof q->pos);
        frame(p, q->ex, q->ey, q->ez);
        double tilt = acos(fmax(-1.0, fmin(1.0, -p->aim[2] / r)));
        q->scale = mf * lx_luminaire_tilt_factor(p->lum, tilt);
        /* LM-63 / EULUMDAT: the length lies along C0-C180 (ex), the width along C90-C270 (ey) */
        double w = fabs(p->lum->length_m), l = fabs(p->lum->width_m);
        q->circular = p->lum->width_m < 0 && (p->lum->length_m < 0 || p->lum->length_m == 0);
        if (q->circular) w = l = fabs(p->lum->width_m);
        q->w = w;
        q->l = l;
        q->size_m = q->circular ? w : sqrt(w * w + l * l);
        if (o->interp != LX_INTERP_TABLE) continue;
        for (size_t k = 0; k < i; k++)
            if (pl[k].lum == p->lum) { /* share the table of the same luminaire */
                q->table = pl[k].table;
                q->ns = pl[k].ns;
                q->nq = pl[k].nq;
                q->cols = pl[k].cols;
                q->toff = pl[k].toff;
                q->pair = pl[k].pair;
                break;
            }
        if (!q->table) {
            own[i] = build_table(p->lum, ns, nq, &q->cols, &q->pair);
            if (!own[i]) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the intensity table");
            q->table = own[i];
            q->ns = ns;
            q->nq = q->cols > 1 ? nq : 0;
            q->toff = *tables_n;
            *tables_n += 2 * (size_t)(ns + 1) * (size_t)q->cols;
        }
    }
    return LX_OK;
}

#if LX_OPENCL
/* The OpenCL path: all tables in one buffer, the kernel, then the near-field pass on the CPU unless
 * the model is point. A failure the backend rule allows to fall back on clears *use_cl. */
static lx_status grid_run_opencl(lx_ctx *ctx, const plum *pl, size_t m, float *const *own, size_t tables_n,
                                 const double *points, size_t n, const double *normals, int shared_normal,
                                 const lx_grid_opts *o, double tol, double *E, lx_backend *used, int *use_cl)
{
    float *all = lx__alloc_n(tables_n, sizeof *all);
    if (!all) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; i < m; i++)
        if (own[i]) memcpy(all + pl[i].toff, own[i], 2 * (size_t)(pl[i].ns + 1) * (size_t)pl[i].cols * sizeof *all);
    lx_status st = lx__grid_opencl(ctx, pl, m, all, tables_n, points, n, normals, shared_normal, o->fp32, E);
    lx__free(all);
    if (st == LX_OK) {
        *used = LX_BACKEND_OPENCL;
    } else if (!lx__backend_fallback(ctx, "grid", o->backend, st)) {
        return st;
    } else {
        *use_cl = 0;
        st = LX_OK;
    }
    if (*use_cl && o->model != LX_MODEL_POINT)
        st = run_jobs(ctx, pl, m, points, n, normals, shared_normal, o->interp, o->model, tol, o->threads, 1, E);
    return st;
}
#endif

/* The illuminances into E: the backend chosen by the rule (OpenCL for the table interpolation only),
 * the CPU jobs otherwise or after a fallback. */
static lx_status grid_compute(lx_ctx *ctx, const plum *pl, size_t m, float *const *own, size_t tables_n,
                              const double *points, size_t n, const double *normals, int shared_normal,
                              const lx_grid_opts *o, double tol, double *E, lx_backend *used)
{
    lx_status st = LX_OK;
    int use_cl = 0;
    if (o->interp == LX_INTERP_TABLE && m > 0) {
        lx_backend be;
        st = lx__backend_choose(ctx, "grid", o->backend, (double)n * (double)m, LX_GRID_CL_COLD, LX_GRID_CL_WARM, &be);
        if (st) return st;
        use_cl = be == LX_BACKEND_OPENCL;
    }
#if LX_OPENCL
    if (use_cl) {
        st = grid_run_opencl(ctx, pl, m, own, tables_n, points, n, normals, shared_normal, o, tol, E, used, &use_cl);
        if (st) return st;
    }
#else
    (void)own, (void)tables_n, (void)used;
#endif
    if (!use_cl) {
        if (m == 0)
            memset(E, 0, n * sizeof *E);
        else
            st = run_jobs(ctx, pl, m, points, n, normals, shared_normal, o->interp, o->model, tol, o->threads, 0, E);
    }
    return st;
}

/* Never a NaN or an infinity handed on as an illuminance: the first such point is an error. */
static lx_status grid_check_finite(lx_ctx *ctx, const lx_placement *lums, size_t m, const double *points, size_t n,
                                   const double *E, lx_interp interp)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(E[i])) {
            double peak = 0;
            for (size_t k = 0; k < m; k++)
                for (size_t j = 0; j < lums[k].lum->n_c * lums[k].lum->n_g; j++)
                    peak = fmax(peak, fabs(lums[k].lum->full_cd[j]));
            char mb[48];
            lx__fmt_magnitude(mb, sizeof mb, peak);
            return lx__error(ctx, LX_ERANGE, NULL, 0,
                             "illuminance at point %zu (%g, %g, %g m) is %s: intensities up to %s cd%s leave the range "
                             "of the arithmetic",
                             i + 1, points[3 * i], points[3 * i + 1], points[3 * i + 2],
                             isnan(E[i]) ? "NaN" : "infinite", mb,
                             interp == LX_INTERP_TABLE ? " (float tables: 3.4e38)" : "");
        }
    return LX_OK;
}

/* A luminaire closer to a receiver point than double arithmetic resolves (d^2 below DBL_MIN: 1.5e-154
 * m) and in front of it, or on the point itself: refused with the point named, never the 0 lx that
 * the loops' d^2 > 0 test gave an underflowed distance (1e-155 m was an overflow error, 1e-162 m
 * 0 lx). Only luminaires that close to the points' bounding box are looked at point by point, so the
 * cost is O(n + m) on every real grid. The distance is computed on the vector scaled by 2^600 (exact). */
static lx_status grid_check_near(lx_ctx *ctx, const lx_placement *lums, size_t m, const double *points, size_t n,
                                 const double *normals, int shared_normal)
{
    const double r = 1.5e-154; /* > sqrt(DBL_MIN) = 1.49e-154 */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) lo[c] = fmin(lo[c], points[3 * i + c]), hi[c] = fmax(hi[c], points[3 * i + c]);
    for (size_t k = 0; k < m; k++) {
        const double *p = lums[k].pos_m;
        if (p[0] < lo[0] - r || p[0] > hi[0] + r || p[1] < lo[1] - r || p[1] > hi[1] + r || p[2] < lo[2] - r ||
            p[2] > hi[2] + r)
            continue;
        for (size_t i = 0; i < n; i++) {
            const double *q = points + 3 * i, *nv = normals + 3 * (shared_normal ? 0 : i);
            double w[3] = {ldexp(q[0] - p[0], 600), ldexp(q[1] - p[1], 600), ldexp(q[2] - p[2], 600)};
            double d2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2]; /* the true d^2 times 2^1200 */
            if (!(d2 < ldexp(DBL_MIN, 1200))) continue;
            if (d2 == 0)
                return lx__error(ctx, LX_ERANGE, NULL, 0,
                                 "luminaire %zu sits on point %zu (%g, %g, %g m): a point source's illuminance there is "
                                 "undefined",
                                 k + 1, i + 1, q[0], q[1], q[2]);
            if (-(w[0] * nv[0] + w[1] * nv[1] + w[2] * nv[2]) <= 0) continue; /* behind the receiver: 0 lx */
            return lx__error(ctx, LX_ERANGE, NULL, 0,
                             "luminaire %zu is %g m from point %zu (%g, %g, %g m), closer than double arithmetic "
                             "resolves (1.5e-154 m): its illuminance there leaves the double range",
                             k + 1, ldexp(sqrt(d2), -600), i + 1, q[0], q[1], q[2]);
        }
    }
    return LX_OK;
}

lx_status lx_grid_illuminance(lx_ctx *ctx, const lx_placement *lums, size_t m, const double *points, size_t n,
                              const double *normals, int shared_normal, const lx_grid_opts *opts, double *E_lx)
{
    LX__NEED_CTX(ctx);
    if ((!lums && m) || !points || !normals || !E_lx)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_grid_illuminance: NULL argument");
    lx_grid_opts o;
    memset(&o, 0, sizeof o);
    if (opts) o = *opts;
    double mf = 1, tol = 0;
    lx_status st = grid_check_opts(ctx, &o, normals, n, shared_normal, &mf, &tol);
    if (st) return st;
    plum *pl = lx__calloc(m ? m : 1, sizeof *pl);
    if (!pl) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    float **own = lx__calloc(m ? m : 1, sizeof *own);
    double *E = lx__alloc_n(n ? n : 1, sizeof *E);
    if (!own || !E) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto out;
    }
    size_t tables_n = 0;
    lx_backend used = LX_BACKEND_CPU;
    st = grid_check_near(ctx, lums, m, points, n, normals, shared_normal);
    if (st == LX_OK) st = grid_place(ctx, lums, m, &o, mf, pl, own, &tables_n);
    if (st == LX_OK) st = grid_compute(ctx, pl, m, own, tables_n, points, n, normals, shared_normal, &o, tol, E, &used);
    if (st == LX_OK) st = grid_check_finite(ctx, lums, m, points, n, E, o.interp);
    if (st == LX_OK) {
        memcpy(E_lx, E, n * sizeof *E);
        lx__backend_used(ctx, used);
    }
out:
    if (own)
        for (size_t i = 0; i < m; i++)
            lx__free(own[i]);
    lx__free(own);
    lx__free(pl);
    lx__free(E);
    return st;
}

#if LX_OPENCL
/* The OpenCL path: kernels lx_grid_f64 / lx_grid_f32 of kernels/grid.cl. Luminaire records of 16
 * reals: pos, ex, ey, ez, scale, cols, ns, nq, table offset (as reals, exact below 2^24 in float). */
lx_status lx__grid_opencl(lx_ctx *ctx, const plum *pl, size_t m, const float *tables, size_t tables_n, const double *pts,
                          size_t n, const double *nrm, int shared, int fp32, double *E)
{
    lx__cl *cl = NULL;
    lx_status st = lx__cl_get(ctx, &cl);
    if (st) return st;
    int f64 = !fp32 && cl->info.fp64;
    size_t rs = f64 ? sizeof(double) : sizeof(float);
    cl_kernel k = NULL;
    if ((st = lx__cl_kernel(ctx, cl, f64 ? "lx_grid_f64" : "lx_grid_f32", &k))) return st;
    size_t nn = shared ? 1 : n;
    void *hp = lx__alloc(3 * n * rs), *hn = lx__alloc(3 * nn * rs), *hl = lx__alloc(16 * m * rs), *he = lx__alloc(n * rs);
    cl_mem bp = NULL, bn = NULL, bl = NULL, bt = NULL, be = NULL;
    cl_int err = CL_SUCCESS;
    if (!hp || !hn || !hl || !he) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto out;
    }
    /* points as structure of arrays: x[n], y[n], z[n] */
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            if (f64) ((double *)hp)[c * n + i] = pts[3 * i + c];
            else ((float *)hp)[c * n + i] = (float)pts[3 * i + c];
        }
    for (size_t i = 0; i < nn; i++)
        for (int c = 0; c < 3; c++) {
            if (f64) ((double *)hn)[c * nn + i] = nrm[3 * i + c];
            else ((float *)hn)[c * nn + i] = (float)nrm[3 * i + c];
        }
    for (size_t i = 0; i < m; i++) {
        double r[16] = {pl[i].pos[0], pl[i].pos[1], pl[i].pos[2], pl[i].ex[0], pl[i].ex[1], pl[i].ex[2],
                        pl[i].ey[0],  pl[i].ey[1],  pl[i].ey[2],  pl[i].ez[0], pl[i].ez[1], pl[i].ez[2],
                        pl[i].scale,  pl[i].cols,   pl[i].ns,     (double)pl[i].toff};
        (void)0;
        for (int c = 0; c < 16; c++) {
            if (f64) ((double *)hl)[16 * i + c] = r[c];
            else ((float *)hl)[16 * i + c] = (float)r[c];
        }
        if (!f64 && pl[i].toff >= (1u << 24)) {
            st = lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "grid: tables too large for the float kernel");
            goto out;
        }
    }
    /* nq is implied: cols = 4 nq + 1 */
    bp = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, 3 * n * rs, hp, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(points)"))) goto out;
    bn = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, 3 * nn * rs, hn, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(normals)"))) goto out;
    bl = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, 16 * m * rs, hl, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(luminaires)"))) goto out;
    bt = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, tables_n * sizeof(float), (void *)tables, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(tables)"))) goto out;
    be = clCreateBuffer(cl->context, CL_MEM_WRITE_ONLY, n * rs, NULL, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(E)"))) goto out;
    cl_uint un = (cl_uint)n, um = (cl_uint)m, ush = (cl_uint)(shared != 0);
    err = clSetKernelArg(k, 0, sizeof bp, &bp);
    err |= clSetKernelArg(k, 1, sizeof bn, &bn);
    err |= clSetKernelArg(k, 2, sizeof ush, &ush);
    err |= clSetKernelArg(k, 3, sizeof bl, &bl);
    err |= clSetKernelArg(k, 4, sizeof um, &um);
    err |= clSetKernelArg(k, 5, sizeof bt, &bt);
    err |= clSetKernelArg(k, 6, sizeof be, &be);
    err |= clSetKernelArg(k, 7, sizeof un, &un);
    if ((st = lx__cl_check(ctx, err, "clSetKernelArg(grid)"))) goto out;
    size_t local = 64, global = (n + local - 1) / local * local;
    err = clEnqueueNDRangeKernel(cl->queue, k, 1, NULL, &global, &local, 0, NULL, NULL);
    if ((st = lx__cl_check(ctx, err, "clEnqueueNDRangeKernel(grid)"))) goto out;
    err = clEnqueueReadBuffer(cl->queue, be, CL_TRUE, 0, n * rs, he, 0, NULL, NULL);
    if ((st = lx__cl_check(ctx, err, "clEnqueueReadBuffer(grid)"))) goto out;
    for (size_t i = 0; i < n; i++) E[i] = f64 ? ((double *)he)[i] : (double)((float *)he)[i];
out:
    if (bp) clReleaseMemObject(bp);
    if (bn) clReleaseMemObject(bn);
    if (bl) clReleaseMemObject(bl);
    if (bt) clReleaseMemObject(bt);
    if (be) clReleaseMemObject(be);
    if (k) clReleaseKernel(k);
    lx__free(hp);
    lx__free(hn);
    lx__free(hl);
    lx__free(he);
    return st;
}
#endif
