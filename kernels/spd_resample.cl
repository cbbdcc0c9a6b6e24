/* spd_resample.cl - resamples spectra given on their own wavelengths onto one uniform grid by
 * linear interpolation, zero outside each spectrum (the piecewise-linear model of the exact
 * method). CPU twin: resample_cpu and resample_at in src/spectral/batch.c (same formula, same operation order). */
#if LX_FP64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable

#define LX_RESAMPLE_KERNEL(NAME, T)                                                                    \
__kernel void NAME(__global const double *lam, __global const double *val, __global const ulong *offset, \
                   __global const uint *n_in, uint n_spectra, double start_nm, double step_nm,         \
                   uint n_out, ulong stride, __global T *dst)                                          \
{                                                                                                      \
    ulong i = get_global_id(0);                                                                        \
    if (i >= n_spectra) return;                                                                        \
    __global const double *x = lam + offset[i];                                                        \
    __global const double *y = val + offset[i];                                                        \
    uint n = n_in[i], lo = 0;                                                                          \
    __global T *o = dst + i * stride;                                                                  \
    for (uint j = 0; j < n_out; j++) {                                                                 \
        double xq = start_nm + (double)j * step_nm;                                                    \
        double r = 0.0;                                                                                \
        if (n >= 1 && xq >= x[0] && xq <= x[n - 1]) {                                                 \
            while (lo + 2 < n && x[lo + 1] <= xq) lo++;                                                \
            uint hi = lo + 1 < n ? lo + 1 : lo;                                                        \
            if (xq == x[lo]) r = y[lo];                                                                \
            else if (xq == x[hi]) r = y[hi];                                                           \
            else {                                                                                     \
                double t = (xq - x[lo]) / (x[hi] - x[lo]);                                             \
                r = y[lo] + t * (y[hi] - y[lo]);                                                       \
            }                                                                                          \
        }                                                                                              \
        o[j] = (T)r;                                                                                   \
    }                                                                                                  \
}

LX_RESAMPLE_KERNEL(spd_resample_f32, float)
LX_RESAMPLE_KERNEL(spd_resample_f64, double)
#endif
