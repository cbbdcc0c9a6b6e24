/* unc_trials.cl - the Monte Carlo trials of the uncertainty engine in the space of the integrals:
 * per trial its Philox4x32-10 normal and uniform deviates (Box-Muller) and the change of the K
 * integrals they make, G z + the shift's table + the bandwidths' + the Fourier components'. CPU
 * twin (the reference, in double): src/spectral/unc_trials.c with src/spectral/unc_rng.c. One
 * work-item per trial; the output is column-major, dl[k * count + t], so neighbouring work-items
 * write neighbouring words. real is double with LX_FP64, else float. */

#if LX_FP64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double unc_real;
#define UNC_TWO_PI 6.283185307179586
#define UNC_UNIT(w) (((double)(w) + 0.5) * 2.3283064365386963e-10)
#else
typedef float unc_real;
#define UNC_TWO_PI 6.2831853f
#define UNC_UNIT(w) (((float)((w) >> 8) + 0.5f) * 5.9604645e-8f) /* the top 24 bits: never 0 or 1 */
#endif

inline uint4 unc_philox(uint4 c, uint2 k)
{
    for (int r = 0; r < 10; r++) {
        uint hi0 = mul_hi(0xD2511F53u, c.x), lo0 = 0xD2511F53u * c.x;
        uint hi1 = mul_hi(0xCD9E8D57u, c.z), lo1 = 0xCD9E8D57u * c.z;
        c = (uint4)(hi1 ^ c.y ^ k.x, lo1, hi0 ^ c.w ^ k.y, lo0);
        k += (uint2)(0x9E3779B9u, 0xBB67AE85u);
    }
    return c;
}

inline uint4 unc_block(ulong seed, ulong t, uint b, uint stream)
{
    return unc_philox((uint4)((uint)t, (uint)(t >> 32), b, stream), (uint2)((uint)seed, (uint)(seed >> 32)));
}

/* normal deviate i of trial t (Box-Muller on the block's uniforms, as lx__unc_normal4) */
inline unc_real unc_normal(ulong seed, ulong t, uint i)
{
    uint4 w = unc_block(seed, t, i / 4, 0);
    uint a = (i & 2) ? w.z : w.x, b = (i & 2) ? w.w : w.y;
    unc_real r = sqrt(-2 * log(UNC_UNIT(a))), ang = UNC_TWO_PI * UNC_UNIT(b);
    return (i & 1) ? r * sin(ang) : r * cos(ang);
}

inline unc_real unc_uniform(ulong seed, ulong t, uint i)
{
    uint4 w = unc_block(seed, t, i / 4, 1);
    uint a = (i & 3) == 0 ? w.x : (i & 3) == 1 ? w.y : (i & 3) == 2 ? w.z : w.w;
    return UNC_UNIT(a);
}

/* count trials from t0. G: r x K (the normal part's factor, column by column); the shift table:
 * ns breakpoints sd and ns x K values sT (ns 0: no shift), shift_sigma; nbw bandwidth components
 * (bw: sigma, b0 pairs; bwD: nbw x K); nf Fourier components (fs: sigma, terms pairs; F: their
 * (2 N + 1) x K vectors one after another). dl: K x count. */
__kernel void unc_trials(ulong seed, ulong t0, uint count, uint K, uint r, __global const unc_real *G,
                         uint ns, unc_real shift_sigma, __global const unc_real *sd, __global const unc_real *sT,
                         uint nbw, __global const unc_real *bw, __global const unc_real *bwD,
                         uint nf, __global const unc_real *fs, __global const unc_real *F, __global unc_real *dl)
{
    uint t = get_global_id(0);
    if (t >= count) return;
    ulong tt = t0 + t;
    for (uint k = 0; k < K; k++) dl[(ulong)k * count + t] = 0;
    /* the normal part: four deviates a block */
    for (uint j = 0; j < r; j += 4) {
        uint4 w = unc_block(seed, tt, j / 4, 0);
        unc_real r0 = sqrt(-2 * log(UNC_UNIT(w.x))), a0 = UNC_TWO_PI * UNC_UNIT(w.y);
        unc_real r1 = sqrt(-2 * log(UNC_UNIT(w.z))), a1 = UNC_TWO_PI * UNC_UNIT(w.w);
        unc_real z[4] = {r0 * cos(a0), r0 * sin(a0), r1 * cos(a1), r1 * sin(a1)};
        uint m = r - j < 4 ? r - j : 4;
        for (uint k = 0; k < K; k++) {
            unc_real s = dl[(ulong)k * count + t];
            for (uint q = 0; q < m; q++) s += z[q] * G[(ulong)(j + q) * K + k];
            dl[(ulong)k * count + t] = s;
        }
    }
    uint iz = r, iu = 0;
    if (shift_sigma > 0) {
        unc_real d = shift_sigma * unc_normal(seed, tt, iz++);
        uint lo = 0, hi = ns - 1;
        if (d <= sd[0]) hi = 1;
        else if (d >= sd[hi]) lo = hi - 1;
        else
            while (hi - lo > 1) {
                uint mid = (lo + hi) / 2;
                if (sd[mid] <= d) lo = mid;
                else hi = mid;
            }
        unc_real f = (d - sd[lo]) / (sd[hi] - sd[lo]);
        for (uint k = 0; k < K; k++) {
            unc_real a = sT[(ulong)lo * K + k], b = sT[(ulong)hi * K + k];
            dl[(ulong)k * count + t] += a + f * (b - a);
        }
    }
    for (uint b = 0; b < nbw; b++) {
        unc_real d = bw[2 * b] * unc_normal(seed, tt, iz++), b0 = bw[2 * b + 1];
        unc_real c = (2 * b0 * d + d * d) / 12;
        for (uint k = 0; k < K; k++) dl[(ulong)k * count + t] += c * bwD[(ulong)b * K + k];
    }
    ulong fo = 0;
    for (uint f = 0; f < nf; f++) {
        unc_real sigma = fs[2 * f];
        uint N = (uint)fs[2 * f + 1];
        unc_real nrm = 0;
        for (uint i = 0; i <= N; i++) {
            unc_real y = unc_normal(seed, tt, iz + i);
            nrm += y * y;
        }
        unc_real s = sigma / sqrt(nrm);
        unc_real y0 = s * unc_normal(seed, tt, iz);
        for (uint k = 0; k < K; k++) dl[(ulong)k * count + t] += y0 * F[fo + k];
        for (uint i = 1; i <= N; i++) {
            unc_real y = s * unc_normal(seed, tt, iz + i), a = UNC_TWO_PI * unc_uniform(seed, tt, iu + i - 1);
            unc_real cs = y * cos(a), sn = y * sin(a);
            __global const unc_real *Fs = F + fo + (ulong)(2 * i - 1) * K;
            for (uint k = 0; k < K; k++) dl[(ulong)k * count + t] += cs * Fs[k] + sn * Fs[K + k];
        }
        iz += N + 1, iu += N;
        fo += (ulong)(2 * N + 1) * K;
    }
}
