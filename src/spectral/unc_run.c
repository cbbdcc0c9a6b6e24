/* unc_run.c - the uncertainty of one spectrum's quantities: the model bound to the spectrum and
 * carried into the space of the integrals (unc_space.c), the estimates, the GUM law of propagation
 * with the providers' derivatives (JCGM 100 5.1.2) and its budget, Monte Carlo trials on every
 * core with JCGM 101's adaptive procedure (7.9), and the validation of GUM against Monte Carlo
 * (JCGM 101 8). The colour layer calls it with its providers added (colour/unc_colour.c). */
#include "spectral/unc_private.h"
#include "spectral/unc_stats.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char *const qnames[LX_UQ_COUNT] = {
    "X", "Y", "Z", "x", "y", "u_prime", "v_prime", "cct_K", "duv", "ler_lm_per_W", "scotopic_Y", "sp_ratio", "radiant",
    "alphaopic_sc", "alphaopic_mc", "alphaopic_lc", "alphaopic_rh", "alphaopic_mel",
    "cyanopic_edi", "chloropic_edi", "erythropic_edi", "rhodopic_edi", "melanopic_edi",
    "cyanopic_der", "chloropic_der", "erythropic_der", "rhodopic_der", "melanopic_der",
    "par_ppfd", "par_epar", "par_ypf",
    "cri_ra", "cri_r1", "cri_r2", "cri_r3", "cri_r4", "cri_r5", "cri_r6", "cri_r7", "cri_r8", "cri_r9", "cri_r10",
    "cri_r11", "cri_r12", "cri_r13", "cri_r14", "tm30_rf", "tm30_rg"};

const char *lx_unc_quantity_name(lx_unc_quantity q) { return (int)q >= 0 && q < LX_UQ_COUNT ? qnames[q] : NULL; }

unsigned lx__unc_group(int q)
{
    return q <= LX_UQ_RADIANT ? LX_UNC_COLORIMETRY : q <= LX_UQ_DER_MEL ? LX_UNC_ALPHAOPIC : q <= LX_UQ_YPF ? LX_UNC_PAR
           : q <= LX_UQ_R14 ? LX_UNC_CRI : LX_UNC_TM30;
}

void lx_unc_result_free(lx_unc_result *r)
{
    if (!r) return;
    lx__free(r->q);
    lx__free(r->history_trials), lx__free(r->history_ratio), lx__free(r->history_worst);
    lx__free(r);
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct run {
    lx_ctx *ctx;
    const lx_spd *spd;
    lx_unc_opts o;
    const lx__unc_provider *prov;
    size_t nprov;
    lx__unc_space sp;
    lx__unc_bound *b;
    size_t ncomp;
    size_t nout, maxout;
    size_t *pout, *pint; /* per provider: its first output and first integral */
    double *y0, *J;      /* nout; nout x K */
    int *qid, *slot;     /* per output: its quantity; its storage row (-1: not stored) */
    size_t ns, cap;      /* stored quantities; trials of room */
    double **vals;       /* ns arrays of cap trials (grown by realloc: large blocks move by remapping) */
    int on_device;       /* trials so far were drawn on OpenCL */
    int redone;          /* the device failed part-way: every trial so far was drawn again on the CPU */
    lx_unc_result *res;
} run;

/* ---- the estimates and the derivatives ---- */

static lx_status eval_at(run *R, const double *L, size_t m, double *y, size_t ldy)
{
    /* every provider on m sets of integrals (row length K), on the caller's context */
    void *scratch[16] = {0};
    for (size_t p = 0; p < R->nprov; p++) {
        const lx__unc_provider *P = &R->prov[p];
        if (P->scratch_new && !(scratch[p] = P->scratch_new(P->self))) {
            for (size_t q = 0; q < p; q++)
                if (R->prov[q].scratch_free) R->prov[q].scratch_free(R->prov[q].self, scratch[q]);
            return lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
        }
    }
    double *tmp = lx__alloc(m * R->maxout * sizeof *tmp);
    lx_status st = tmp ? LX_OK : lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t p = 0; st == LX_OK && p < R->nprov; p++) {
        const lx__unc_provider *P = &R->prov[p];
        P->eval(R->ctx, P->self, scratch[p], m, L + R->pint[p], R->sp.K, tmp, (size_t)P->nout);
        for (size_t t = 0; t < m; t++)
            for (int k = 0; k < P->nout; k++) y[t * ldy + R->pout[p] + (size_t)k] = tmp[t * (size_t)P->nout + (size_t)k];
    }
    lx__free(tmp);
    for (size_t p = 0; p < R->nprov; p++)
        if (R->prov[p].scratch_free) R->prov[p].scratch_free(R->prov[p].self, scratch[p]);
    return st;
}

/* Central differences of provider p's quantities in its integrals: steps of 1e-5 of each integral
 * (the error of the difference O(h^2), of rounding O(eps / h): both near 1e-10 relative). */
static lx_status numeric_jacobian(run *R, size_t p)
{
    const lx__unc_provider *P = &R->prov[p];
    size_t K = R->sp.K, ni = (size_t)P->nint, off = R->pint[p];
    double *L = lx__alloc(2 * ni * K * sizeof *L), *y = lx__alloc(2 * ni * R->nout * sizeof *y);
    if (!L || !y) {
        lx__free(L), lx__free(y);
        return lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    double big = 0.0;
    for (size_t i = 0; i < ni; i++) big = fmax(big, fabs(R->sp.L0[off + i]));
    double *h = lx__alloc(ni * sizeof *h);
    if (!h) {
        lx__free(L), lx__free(y);
        return lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t i = 0; i < ni; i++) {
        double a = fabs(R->sp.L0[off + i]);
        h[i] = 1e-5 * (a > 1e-6 * big ? a : big > 0 ? 1e-6 * big : 1e-300);
        for (int s = 0; s < 2; s++) {
            double *l = L + (2 * i + (size_t)s) * K;
            memcpy(l, R->sp.L0, K * sizeof *l);
            l[off + i] += s ? -h[i] : h[i];
        }
    }
    lx_status st = eval_at(R, L, 2 * ni, y, R->nout);
    for (int k = 0; st == LX_OK && k < P->nout; k++) {
        size_t q = R->pout[p] + (size_t)k;
        for (size_t i = 0; i < ni; i++)
            R->J[q * K + off + i] = (y[(2 * i) * R->nout + q] - y[(2 * i + 1) * R->nout + q]) / (2 * h[i]);
    }
    lx__free(L), lx__free(y), lx__free(h);
    return st;
}

static lx_status jacobians(run *R)
{
    size_t K = R->sp.K;
    R->J = lx__calloc(R->nout * K, sizeof *R->J);
    if (!R->J) return lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t p = 0; p < R->nprov; p++) {
        const lx__unc_provider *P = &R->prov[p];
        size_t ni = (size_t)P->nint, off = R->pint[p];
        double *j = lx__alloc((size_t)P->nout * ni * sizeof *j);
        if (!j) return lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
        if (P->jacobian && P->jacobian(R->ctx, P->self, R->sp.L0 + off, j)) {
            for (int k = 0; k < P->nout; k++)
                for (size_t i = 0; i < ni; i++) R->J[(R->pout[p] + (size_t)k) * K + off + i] = j[(size_t)k * ni + i];
            lx__free(j);
            continue;
        }
        lx__free(j);
        lx_status st = numeric_jacobian(R, p);
        if (st != LX_OK) return st;
    }
    return LX_OK;
}

/* J_q F^T F J_q^T = sum over F's rows of (J_q . row)^2 */
static double quad(const double *Jq, const lx__unc_factor *f, size_t K)
{
    double s = 0.0;
    for (size_t r = 0; r < f->m; r++) {
        const double *v = f->F + r * K;
        double d = 0.0;
        for (size_t i = 0; i < K; i++) d += Jq[i] * v[i];
        s += d * d;
    }
    return s;
}

/* Fourier components with no N: the N (1 .. 50) with the largest GUM u(CCT) (u(x) without a CCT). */
static void fourier_terms(run *R)
{
    size_t K = R->sp.K, qc = (size_t)-1;
    for (size_t k = 0; k < R->nout; k++)
        if (R->qid[k] == LX_UQ_CCT && isfinite(R->y0[k])) qc = k;
    if (qc == (size_t)-1)
        for (size_t k = 0; k < R->nout; k++)
            if (R->qid[k] == LX_UQ_CX && isfinite(R->y0[k])) qc = k;
    for (size_t f = 0; f < R->sp.nfourier; f++) {
        lx__unc_fourier *F = &R->sp.fourier[f];
        if (F->terms) continue;
        F->terms = 3;
        if (qc == (size_t)-1) continue;
        const double *Jq = R->J + qc * K;
        double acc = 0.0, best = -1.0;
        for (int i = 0; i <= lx__unc_fourier_auto_max(); i++) {
            for (int c = i ? 1 : 0; c < (i ? 3 : 1); c++) {
                const double *v = F->F + (i ? (2 * (size_t)i - 2 + (size_t)c) : 0) * K;
                double d = 0.0;
                for (size_t k = 0; k < K; k++) d += Jq[k] * v[k];
                acc += (i ? 0.5 : 1.0) * d * d;
            }
            double var = acc / (i + 1);
            if (i > 0 && var > best && isfinite(var)) best = var, F->terms = i;
        }
    }
}

/* ---- GUM ---- */

static void gum(run *R)
{
    size_t K = R->sp.K, n = R->sp.n;
    lx_unc_result *res = R->res;
    double k = res->k;
    for (size_t q = 0; q < R->nout; q++) {
        lx_unc_value *v = &res->q[R->qid[q]];
        if (!v->defined) continue;
        const double *Jq = R->J + q * K;
        double total = 0.0, best[3] = {-1, -1, -1};
        for (size_t c = 0; c < R->ncomp; c++) {
            double vc = quad(Jq, &R->sp.fac[c], K);
            total += vc;
            for (int t = 0; t < 3; t++) /* the three largest, in order */
                if (vc > best[t]) {
                    for (int s = 2; s > t; s--) best[s] = best[s - 1], v->top[s] = v->top[s - 1];
                    best[t] = vc, v->top[t] = (int)c;
                    break;
                }
        }
        for (int t = 0; t < 3; t++) v->top_u[t] = v->top[t] >= 0 ? sqrt(fmax(best[t], 0.0)) : NAN;
        v->gum_u = sqrt(fmax(total, 0.0));
        if (!isfinite(total)) v->gum_u = NAN;
        v->gum_lo = v->value - k * v->gum_u, v->gum_hi = v->value + k * v->gum_u;
        /* the sample whose relative change moves the quantity most: |dy/dS_j| |S_j| */
        double bestc = -1.0;
        for (size_t j = 0; j < n; j++) {
            double c = 0.0;
            for (size_t i = 0; i < K; i++)
                if (Jq[i] != 0.0) c += Jq[i] * R->sp.A[i * n + j];
            c = fabs(c * R->spd->value[j]);
            if (c > bestc) bestc = c, v->peak_nm = R->spd->lambda_nm[j];
        }
    }
}

/* ---- Monte Carlo ---- */

#define CHUNK 256 /* trials a thread takes at a time */

typedef struct mc_job {
    run *R;
    uint64_t t0;       /* the first trial */
    size_t count;      /* trials */
    const double *L;   /* their integrals when drawn already (OpenCL), else NULL */
    _Atomic size_t next;
    _Atomic int fail;
    _Atomic long long draw_ns; /* the threads' time drawing */
} mc_job;

static void mc_worker(void *arg, int thread)
{
    (void)thread;
    mc_job *j = arg;
    run *R = j->R;
    size_t K = R->sp.K;
    lx_ctx *ctx = NULL;
    void *scratch[16] = {0};
    double *L = lx__alloc(CHUNK * K * sizeof *L), *Y = lx__alloc(CHUNK * R->maxout * sizeof *Y);
    int ok = L && Y && lx_ctx_create(&ctx) == LX_OK;
    for (size_t p = 0; ok && p < R->nprov; p++)
        if (R->prov[p].scratch_new && !(scratch[p] = R->prov[p].scratch_new(R->prov[p].self))) ok = 0;
    if (!ok) atomic_store(&j->fail, 1);
    while (ok && !atomic_load(&j->fail)) {
        size_t a = atomic_fetch_add(&j->next, CHUNK);
        if (a >= j->count) break;
        size_t m = j->count - a < CHUNK ? j->count - a : CHUNK;
        const double *Lc = j->L ? j->L + a * K : L;
        if (!j->L) {
            double d0 = now_s();
            lx__unc_trials_cpu(&R->sp, R->o.seed, j->t0 + a, m, L);
            atomic_fetch_add(&j->draw_ns, (long long)((now_s() - d0) * 1e9));
        }
        for (size_t p = 0; p < R->nprov; p++) {
            const lx__unc_provider *P = &R->prov[p];
            size_t no = (size_t)P->nout;
            P->eval(ctx, P->self, scratch[p], m, Lc + R->pint[p], K, Y, no);
            for (size_t k = 0; k < no; k++) {
                int s = R->slot[R->pout[p] + k];
                if (s < 0) continue;
                double *dst = R->vals[s] + (size_t)j->t0 + a;
                for (size_t t = 0; t < m; t++) dst[t] = Y[t * no + k];
            }
        }
    }
    for (size_t p = 0; p < R->nprov; p++)
        if (scratch[p] && R->prov[p].scratch_free) R->prov[p].scratch_free(R->prov[p].self, scratch[p]);
    lx_ctx_destroy(ctx);
    lx__free(L), lx__free(Y);
}

static lx_status grow(run *R, size_t cap)
{
    if (cap <= R->cap) return LX_OK;
    if (!R->vals && !(R->vals = lx__calloc(R->ns ? R->ns : 1, sizeof *R->vals)))
        return lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t s = 0; s < R->ns; s++) {
        double *v = lx__realloc(R->vals[s], cap * sizeof *v);
        if (!v) return lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory for %zu trials of %zu quantities", cap, R->ns);
        R->vals[s] = v;
    }
    R->cap = cap;
    return LX_OK;
}

/* Trials t0 .. t0 + count - 1 into the store (room made by the caller). */
static lx_status mc_run_cpu(run *R, uint64_t t0, size_t count, const double *L)
{
    mc_job j = {R, t0, count, L, 0, 0, 0};
    int threads = lx__threads(R->o.threads, (long)((count + CHUNK - 1) / CHUNK));
    lx__parallel_run(threads, mc_worker, &j);
    R->res->seconds_draw += 1e-9 * (double)atomic_load(&j.draw_ns) / threads;
    return atomic_load(&j.fail) ? lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory") : LX_OK;
}

/* Trials t0 .. t0 + count - 1 into the store. A run is never part device, part CPU: when the device
 * fails after earlier trials ran on it (and AUTO falls back), those are drawn again on the CPU and
 * the rest of the run stays there. */
static lx_status mc_trials(run *R, uint64_t t0, size_t count)
{
    lx_backend used = LX_BACKEND_CPU;
    double *L = NULL, d0 = now_s();
    lx_status st = lx__unc_trials_device(R->ctx, &R->sp, R->o.seed, t0, count, R->o.backend, &L, &used);
    if (st != LX_OK) return st;
    if (used == LX_BACKEND_OPENCL) R->res->seconds_draw += now_s() - d0;
    if (used == LX_BACKEND_CPU && R->on_device) {
        R->o.backend = LX_BACKEND_CPU, R->on_device = 0, R->redone = 1;
        if ((st = mc_run_cpu(R, 0, (size_t)t0, NULL)) != LX_OK) return st;
    }
    if (used == LX_BACKEND_OPENCL) R->on_device = 1;
    st = mc_run_cpu(R, t0, count, L);
    lx__free(L);
    R->res->backend = used;
    return st;
}

typedef struct seq_stats {
    double *mean, *u, *lo, *hi, *n; /* per sequence, per stored quantity: [h * ns + s] (n: its finite values) */
    size_t h, cap;
} seq_stats;

static int seq_push(run *R, seq_stats *S, size_t first, size_t M, double *tmp)
{
    if (S->h == S->cap) {
        size_t cap = S->cap ? 2 * S->cap : 16;
        double *p = lx__realloc(S->mean, 5 * cap * R->ns * sizeof *p);
        if (!p) return -1;
        /* the five blocks move apart as the room grows */
        for (int b = 4; b >= 1; b--) memmove(p + b * cap * R->ns, p + b * S->cap * R->ns, S->h * R->ns * sizeof *p);
        S->mean = p, S->u = p + cap * R->ns, S->lo = p + 2 * cap * R->ns, S->hi = p + 3 * cap * R->ns;
        S->n = p + 4 * cap * R->ns;
        S->cap = cap;
    }
    for (size_t s = 0; s < R->ns; s++) {
        lx__unc_stat st;
        lx__unc_stats(R->vals[s] + first, M, R->o.coverage, R->o.shortest, tmp, &st);
        size_t i = S->h * R->ns + s;
        S->mean[i] = st.mean, S->u[i] = st.u, S->lo[i] = st.lo, S->hi[i] = st.hi, S->n[i] = (double)st.n;
    }
    S->h++;
    return 0;
}

/* The standard deviation of the average of h values a[k * ns + s] (JCGM 101 7.9.4 d). */
static double sd_of_mean(const double *a, size_t h, size_t ns, size_t s)
{
    double m = 0.0, ss = 0.0;
    for (size_t k = 0; k < h; k++) m += a[k * ns + s];
    m /= (double)h;
    for (size_t k = 0; k < h; k++) ss += (a[k * ns + s] - m) * (a[k * ns + s] - m);
    return sqrt(ss / ((double)h * (double)(h - 1)));
}

/* The standard deviation of all the sequences' values together, from their means and deviations. */
static double pooled_u(const seq_stats *S, size_t ns, size_t s)
{
    double n = 0.0, m = 0.0, ss = 0.0;
    for (size_t k = 0; k < S->h; k++)
        if (S->n[k * ns + s] > 0) n += S->n[k * ns + s], m += S->n[k * ns + s] * S->mean[k * ns + s];
    if (!(n > 1)) return NAN;
    m /= n;
    for (size_t k = 0; k < S->h; k++) {
        double nk = S->n[k * ns + s], d = S->mean[k * ns + s] - m;
        if (nk > 0) ss += (nk - 1) * S->u[k * ns + s] * S->u[k * ns + s] + nk * d * d;
    }
    return sqrt(ss / (n - 1));
}

/* The largest 2 s / delta over the stored quantities after S->h sequences (delta from the pooled
 * u); *worst its quantity. A quantity undefined in every trial of a sequence is left out. */
static double stability(run *R, const seq_stats *S, int *worst, int *stable_of)
{
    double ratio = 0.0;
    *worst = -1;
    for (size_t s = 0; s < R->ns; s++) {
        size_t q = 0;
        while (R->slot[q] != (int)s) q++;
        double d = lx__unc_tolerance(pooled_u(S, R->ns, s), R->y0[q], R->o.digits), r = 0.0;
        const double *a[4] = {S->mean, S->u, S->lo, S->hi};
        for (int k = 0; k < 4; k++) {
            double sd = sd_of_mean(a[k], S->h, R->ns, s);
            if (isfinite(sd)) r = fmax(r, 2.0 * sd / d);
        }
        stable_of[s] = r <= 1.0;
        if (r > ratio || *worst < 0) ratio = fmax(ratio, r), *worst = R->qid[q];
    }
    return ratio;
}

static int history_push(lx_unc_result *res, size_t trials, double ratio, int worst)
{
    size_t n = res->nhistory + 1;
    size_t *t = lx__realloc(res->history_trials, n * sizeof *t);
    if (t) res->history_trials = t;
    double *r = lx__realloc(res->history_ratio, n * sizeof *r);
    if (r) res->history_ratio = r;
    int *w = lx__realloc(res->history_worst, n * sizeof *w);
    if (w) res->history_worst = w;
    if (!t || !r || !w) return -1;
    t[n - 1] = trials, r[n - 1] = ratio, w[n - 1] = worst;
    res->nhistory = n;
    return 0;
}

static lx_status monte_carlo(run *R)
{
    lx_unc_result *res = R->res;
    double p = R->o.coverage;
    size_t M = (size_t)ceil(100.0 / (1.0 - p));
    if (M < 10000) M = 10000;
    size_t fixed = R->o.trials, total = 0;
    /* the most trials: as asked, else as many as 512 MB of values hold, at most 10^7 */
    size_t maxt = R->o.max_trials ? R->o.max_trials : ((size_t)1 << 26) / (R->ns ? R->ns : 1);
    if (!R->o.max_trials && maxt > 10000000) maxt = 10000000;
    seq_stats S = {0};
    int *stable_of = lx__calloc(R->ns + 1, sizeof *stable_of);
    double *tmp = lx__alloc((fixed > M ? fixed : M) * sizeof *tmp);
    lx_status st = stable_of && tmp ? LX_OK : lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    int all_stable = -1;
    size_t most = ((size_t)1 << 31) / sizeof(double) / (R->ns ? R->ns : 1); /* 2 GB of trial values */
    if (st == LX_OK && fixed > most)
        st = lx__error(R->ctx, LX_EINVAL, NULL, 0,
                       "%zu trials of %zu quantities would hold %.1f GB of values; at most %zu trials (2 GB)", fixed,
                       R->ns, (double)fixed * (double)R->ns * 8e-9, most);
    if (st == LX_OK && fixed) {
        if ((st = grow(R, fixed)) == LX_OK && (st = mc_trials(R, 0, fixed)) == LX_OK) total = fixed;
        /* the stability of the trials asked for, over the whole sequences they hold */
        for (size_t h = 0; st == LX_OK && (h + 1) * M <= fixed; h++)
            if (seq_push(R, &S, h * M, M, tmp)) st = lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
        if (st == LX_OK && S.h >= 2) {
            int worst;
            double ratio = stability(R, &S, &worst, stable_of);
            history_push(res, S.h * M, ratio, worst);
            all_stable = ratio <= 1.0;
        }
    }
    while (st == LX_OK && !fixed) {
        size_t next = total + M;
        if (next > maxt) break;
        if ((st = grow(R, next > R->cap ? 2 * next : next)) != LX_OK) break;
        if ((st = mc_trials(R, total, M)) != LX_OK) break;
        if (R->redone) { /* the sequences so far again, from the CPU's trials */
            R->redone = 0, S.h = 0, res->nhistory = 0;
            for (size_t h = 0; h * M < total && st == LX_OK; h++)
                if (seq_push(R, &S, h * M, M, tmp)) st = lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
            if (st != LX_OK) break;
        }
        if (seq_push(R, &S, total, M, tmp)) {
            st = lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
            break;
        }
        total = next;
        if (S.h < 2) continue;
        int worst;
        double ratio = stability(R, &S, &worst, stable_of);
        history_push(res, total, ratio, worst);
        if (ratio <= 1.0) {
            all_stable = 1;
            break;
        }
        all_stable = 0;
    }
    if (st == LX_OK && total > (fixed > M ? fixed : M)) {
        double *t2 = lx__realloc(tmp, total * sizeof *tmp);
        if (t2) tmp = t2;
        else st = lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    if (st == LX_OK) {
        if (!fixed) res->sequence = M;
        res->trials = total;
        res->stable = all_stable;
        for (size_t q = 0; q < R->nout; q++) {
            int s = R->slot[q];
            if (s < 0) continue;
            lx_unc_value *v = &res->q[R->qid[q]];
            lx__unc_stat ss;
            if (!lx__unc_stats(R->vals[s], total, p, R->o.shortest, tmp, &ss)) {
                v->undefined = 1.0;
                continue;
            }
            v->mc_mean = ss.mean, v->mc_u = ss.u, v->mc_lo = ss.lo, v->mc_hi = ss.hi, v->undefined = ss.undefined;
            v->stable = all_stable < 0 ? -1 : stable_of[s];
        }
    }
    lx__free(S.mean), lx__free(stable_of), lx__free(tmp);
    return st;
}

/* ---- the run ---- */

static lx_status options(lx_ctx *ctx, const lx_unc_opts *in, lx_unc_opts *o)
{
    lx_unc_opts z;
    memset(&z, 0, sizeof z);
    *o = in ? *in : z;
    lx_status st = lx__check_reserved(ctx, "uncertainty options", o->reserved, sizeof o->reserved);
    if (st != LX_OK) return st;
    if ((int)o->method < 0 || o->method > LX_UNC_BOTH)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: unknown method %d", (int)o->method);
    if (!o->quantities) o->quantities = LX_UNC_COLORIMETRY;
    if (!o->observer) o->observer = LX_OBSERVER_2;
    if (o->observer != LX_OBSERVER_2 && o->observer != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)o->observer);
    if (!o->digits) o->digits = 2;
    if (o->digits < 1 || o->digits > 2)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: digits must be 1 or 2, not %d", o->digits);
    if (o->coverage == 0) o->coverage = 0.95;
    if (!(o->coverage > 0 && o->coverage < 1))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: the coverage probability must lie in (0, 1), not %g", o->coverage);
    if (o->trials == 1) return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: Monte Carlo needs at least 2 trials");
    return LX_OK;
}

static lx_status setup(run *R, const lx_unc_model *m)
{
    lx_ctx *ctx = R->ctx;
    size_t nout = 0, K = 0, maxout = 0;
    R->pout = lx__alloc(2 * R->nprov * sizeof *R->pout);
    if (!R->pout) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    R->pint = R->pout + R->nprov;
    for (size_t p = 0; p < R->nprov; p++) {
        R->pout[p] = nout, R->pint[p] = K;
        nout += (size_t)R->prov[p].nout, K += (size_t)R->prov[p].nint;
        if ((size_t)R->prov[p].nout > maxout) maxout = (size_t)R->prov[p].nout;
    }
    R->nout = nout, R->maxout = maxout;
    lx_status st = lx__unc_bind(ctx, m, R->spd, &R->b);
    if (st != LX_OK) return st;
    R->ncomp = m->count;
    if ((st = lx__unc_space_make(ctx, R->spd, R->b, R->ncomp, R->prov, R->nprov, &R->sp)) != LX_OK) return st;
    R->y0 = lx__alloc(nout * sizeof *R->y0);
    R->qid = lx__alloc(2 * nout * sizeof *R->qid);
    if (!R->y0 || !R->qid) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    R->slot = R->qid + nout;
    for (size_t p = 0; p < R->nprov; p++)
        for (int k = 0; k < R->prov[p].nout; k++) R->qid[R->pout[p] + (size_t)k] = R->prov[p].out_q[k];
    return eval_at(R, R->sp.L0, 1, R->y0, nout);
}

static lx_status result_new(run *R)
{
    lx_unc_result *res = lx__calloc(1, sizeof *res);
    if (res) res->q = lx__calloc(LX_UQ_COUNT, sizeof *res->q);
    if (!res || !res->q) {
        lx__free(res);
        return lx__error(R->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    R->res = res;
    res->nq = LX_UQ_COUNT, res->method = R->o.method, res->digits = R->o.digits, res->coverage = R->o.coverage;
    res->k = lx__normal_quantile(0.5 * (1.0 + R->o.coverage));
    res->stable = -1, res->backend = LX_BACKEND_CPU, res->rank = R->sp.r;
    for (size_t i = 0; i < LX_UQ_COUNT; i++) {
        lx_unc_value *v = &res->q[i];
        v->value = v->u = v->lo = v->hi = v->mc_mean = v->mc_u = v->mc_lo = v->mc_hi = NAN;
        v->gum_u = v->gum_lo = v->gum_hi = v->delta = v->d_low = v->d_high = v->peak_nm = NAN;
        v->top[0] = v->top[1] = v->top[2] = -1;
        v->top_u[0] = v->top_u[1] = v->top_u[2] = NAN;
        v->stable = v->gum_valid = -1;
    }
    size_t ns = 0;
    int any = 0;
    for (size_t q = 0; q < R->nout; q++) {
        int id = R->qid[q];
        R->slot[q] = -1;
        if (!(lx__unc_group(id) & R->o.quantities) || res->q[id].defined) continue;
        if (!isfinite(R->y0[q])) continue;
        res->q[id].defined = 1, res->q[id].value = R->y0[q], any = 1;
        if (R->o.method != LX_UNC_GUM) R->slot[q] = (int)ns++;
    }
    R->ns = ns;
    for (size_t f = 0; f < R->sp.nfourier; f++) res->fourier_terms = R->sp.fourier[f].terms;
    if (!any) return lx__error(R->ctx, LX_ERANGE, NULL, 0, "uncertainty: no quantity asked for is defined for this spectrum");
    return LX_OK;
}

/* JCGM 101 8.2: GUM's interval y -+ U against Monte Carlo's, within the tolerance of GUM's u. */
static void validate(run *R)
{
    for (size_t i = 0; i < LX_UQ_COUNT; i++) {
        lx_unc_value *v = &R->res->q[i];
        if (!v->defined) continue;
        double gu = v->gum_u, mu = v->mc_u;
        v->u = isfinite(mu) ? mu : gu;
        v->lo = isfinite(mu) ? v->mc_lo : v->gum_lo;
        v->hi = isfinite(mu) ? v->mc_hi : v->gum_hi;
        v->delta = lx__unc_tolerance(isfinite(gu) && R->o.method != LX_UNC_MC ? gu : v->u, v->value, R->o.digits);
        if (R->o.method != LX_UNC_BOTH || !isfinite(gu) || !isfinite(v->mc_lo)) continue;
        v->d_low = fabs(v->gum_lo - v->mc_lo), v->d_high = fabs(v->gum_hi - v->mc_hi);
        /* only against Monte Carlo results stable to delta (JCGM 101 8.1: its interval must be the
         * reference); unstable ones (too few trials) leave the question open */
        if (v->stable == 1) v->gum_valid = v->d_low <= v->delta && v->d_high <= v->delta;
    }
}

static void run_free(run *R)
{
    lx__unc_space_free(&R->sp);
    lx__unc_unbind(R->b, R->ncomp);
    for (size_t s = 0; R->vals && s < R->ns; s++) lx__free(R->vals[s]);
    lx__free(R->pout), lx__free(R->y0), lx__free(R->J), lx__free(R->qid), lx__free(R->vals);
}

lx_status lx__unc_run(lx_ctx *ctx, const lx_spd *spd, const lx_unc_model *m, const lx_unc_opts *opts,
                      const lx__unc_provider *prov, size_t nprov, lx_unc_result **out)
{
    LX__NEED_CTX(ctx);
    if (!out || !m) return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: NULL argument");
    *out = NULL;
    run R;
    memset(&R, 0, sizeof R);
    R.ctx = ctx, R.spd = spd, R.prov = prov, R.nprov = nprov;
    lx_status st = options(ctx, opts, &R.o);
    if (st == LX_OK) st = lx_spd_check(ctx, spd);
    if (st == LX_OK && nprov > 16) st = lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: too many providers");
    double t0 = now_s();
    if (st == LX_OK) st = setup(&R, m);
    if (st == LX_OK) st = jacobians(&R);
    if (st == LX_OK) {
        fourier_terms(&R);
        if (lx__unc_space_finish(&R.sp, R.b) != LX_OK) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    if (st == LX_OK) st = result_new(&R);
    if (st == LX_OK && R.o.method != LX_UNC_MC) gum(&R);
    double t1 = now_s();
    if (st == LX_OK && R.o.method != LX_UNC_GUM) st = monte_carlo(&R);
    if (st == LX_OK) {
        validate(&R);
        R.res->seconds_gum = R.o.method != LX_UNC_MC ? t1 - t0 : 0.0;
        R.res->seconds_mc = R.o.method != LX_UNC_GUM ? now_s() - t1 : 0.0;
        if (R.o.method != LX_UNC_GUM) lx__backend_used(ctx, R.res->backend);
        *out = R.res;
    } else {
        lx_unc_result_free(R.res);
    }
    run_free(&R);
    return st;
}
