/* unc_rng.c - the counter-based generator of the Monte Carlo trials: Philox4x32-10 (Salmon, Moraes,
 * Dror and Shaw, "Parallel random numbers: as easy as 1, 2, 3", SC 2011), uniforms from its 32-bit
 * words and normal deviates by Box-Muller. A trial's numbers depend only on (seed, trial, block), so
 * any split of the trials over threads, and the OpenCL kernel (kernels/unc_trials.cl, its twin), draw
 * the same ones. */
#include "spectral/unc_private.h"

#include <math.h>

#define PHILOX_M0 0xD2511F53u
#define PHILOX_M1 0xCD9E8D57u
#define PHILOX_W0 0x9E3779B9u
#define PHILOX_W1 0xBB67AE85u

void lx__philox4x32(const uint32_t ctr[4], const uint32_t key[2], uint32_t out[4])
{
    uint32_t c0 = ctr[0], c1 = ctr[1], c2 = ctr[2], c3 = ctr[3], k0 = key[0], k1 = key[1];
    for (int r = 0; r < 10; r++) {
        uint64_t p0 = (uint64_t)PHILOX_M0 * c0, p1 = (uint64_t)PHILOX_M1 * c2;
        uint32_t hi0 = (uint32_t)(p0 >> 32), lo0 = (uint32_t)p0, hi1 = (uint32_t)(p1 >> 32), lo1 = (uint32_t)p1;
        c0 = hi1 ^ c1 ^ k0;
        c1 = lo1;
        c2 = hi0 ^ c3 ^ k1;
        c3 = lo0;
        k0 += PHILOX_W0, k1 += PHILOX_W1;
    }
    out[0] = c0, out[1] = c1, out[2] = c2, out[3] = c3;
}

static void block(uint64_t seed, uint64_t trial, uint32_t b, uint32_t stream, uint32_t w[4])
{
    const uint32_t ctr[4] = {(uint32_t)trial, (uint32_t)(trial >> 32), b, stream};
    const uint32_t key[2] = {(uint32_t)seed, (uint32_t)(seed >> 32)};
    lx__philox4x32(ctr, key, w);
}

/* (w + 0.5) 2^-32: in (0, 1), never 0 or 1 */
static double unit(uint32_t w) { return ((double)w + 0.5) * 2.3283064365386963e-10; }

void lx__unc_uniform4(uint64_t seed, uint64_t trial, uint32_t b, double u[4])
{
    uint32_t w[4];
    block(seed, trial, b, LX__UNC_STREAM_UNIFORM, w);
    for (int i = 0; i < 4; i++) u[i] = unit(w[i]);
}

void lx__unc_normal4(uint64_t seed, uint64_t trial, uint32_t b, double z[4])
{
    uint32_t w[4];
    block(seed, trial, b, LX__UNC_STREAM_NORMAL, w);
    for (int i = 0; i < 4; i += 2) {
        double r = sqrt(-2.0 * log(unit(w[i]))), a = 6.283185307179586 * unit(w[i + 1]);
        z[i] = r * cos(a);
        z[i + 1] = r * sin(a);
    }
}
