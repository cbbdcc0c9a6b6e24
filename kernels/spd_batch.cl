/* spd_batch.cl - batch spectral integration: N spectra on one uniform grid against K weighting
 * functions (cie15 rule, weights pre-multiplied by the step). CPU twin: src/spectral/batch.c.
 * Each work-item integrates a contiguous run of per_item spectra with 8-wide vector loads (the
 * layout PoCL's CPU device runs fastest); the accumulation is double (LX_FP64) or compensated float. */

#if LX_FP64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable

#define LX_BATCH_KERNEL(NAME, T, VLOAD_CONVERT)                                                        \
__kernel void NAME(__global const T *v, uint n_spectra, uint n_lambda, ulong stride,                   \
                   __global const double *w, uint k, __global double *out, uint per_item)              \
{                                                                                                      \
    ulong i0 = (ulong)get_global_id(0) * per_item;                                                     \
    ulong i1 = min(i0 + per_item, (ulong)n_spectra);                                                   \
    uint n8 = n_lambda / 8;                                                                            \
    for (ulong i = i0; i < i1; i++) {                                                                  \
        __global const T *row = v + i * stride;                                                        \
        for (uint f = 0; f < k; f++) {                                                                 \
            __global const double *wf = w + (ulong)f * n_lambda;                                       \
            double8 acc = (double8)(0.0);                                                              \
            for (uint j = 0; j < n8; j++) acc = fma(VLOAD_CONVERT(j, row), vload8(j, wf), acc);        \
            double4 a4 = acc.lo + acc.hi;                                                              \
            double2 a2 = a4.lo + a4.hi;                                                                \
            double s = a2.x + a2.y;                                                                    \
            for (uint j = n8 * 8; j < n_lambda; j++) s = fma((double)row[j], wf[j], s);               \
            out[i * k + f] = s;                                                                        \
        }                                                                                              \
    }                                                                                                  \
}

#define LX_LOAD_F32(j, row) convert_double8(vload8((j), (row)))
#define LX_LOAD_F64(j, row) vload8((j), (row))
LX_BATCH_KERNEL(spd_batch_f32, float, LX_LOAD_F32)
LX_BATCH_KERNEL(spd_batch_f64, double, LX_LOAD_F64)
#endif

/* Compensated (Kahan) float accumulation, float weights: the variant for devices without fp64
 * (and the one the README's "double or compensated float" measurement compares). Output float
 * pairs (sum, compensation) are folded on the host. */
__kernel void spd_batch_f32_kahan(__global const float *v, uint n_spectra, uint n_lambda, ulong stride,
                                  __global const float *w, uint k, __global float *out, uint per_item)
{
    ulong i0 = (ulong)get_global_id(0) * per_item;
    ulong i1 = min(i0 + per_item, (ulong)n_spectra);
    uint n8 = n_lambda / 8;
    for (ulong i = i0; i < i1; i++) {
        __global const float *row = v + i * stride;
        for (uint f = 0; f < k; f++) {
            __global const float *wf = w + (ulong)f * n_lambda;
            float8 s = (float8)(0.0f), c = (float8)(0.0f);
            for (uint j = 0; j < n8; j++) {
                float8 y = vload8(j, row) * vload8(j, wf) - c;
                float8 t = s + y;
                c = (t - s) - y;
                s = t;
            }
            /* fold the 8 lanes and the tail with the same compensation */
            float S = 0.0f, C = 0.0f;
            float lanes[8];
            vstore8(s, 0, lanes);
            float comp[8];
            vstore8(c, 0, comp);
            for (int l = 0; l < 8; l++) {
                float y = lanes[l] - comp[l] - C;
                float t = S + y;
                C = (t - S) - y;
                S = t;
            }
            for (uint j = n8 * 8; j < n_lambda; j++) {
                float y = row[j] * wf[j] - C;
                float t = S + y;
                C = (t - S) - y;
                S = t;
            }
            out[2 * (i * k + f)] = S;
            out[2 * (i * k + f) + 1] = -C;
        }
    }
}
