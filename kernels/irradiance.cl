/* irradiance.cl - brute-force irradiance from a lat-long radiance map: one work-item per output
 * normal n sums L_p max(0, n . m_p) over every input pixel, m_p the pixel's exact first moment
 * (row factor x column factor). CPU twin: src/radiance/irradiance_brute.c. The real type is double with
 * LX_FP64, else float with per-row partial sums (two-level summation). */

#if LX_FP64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double lx_irr_real;
#else
typedef float lx_irr_real;
#endif

/* geo: row_s2[H], row_sc_dphi[H], col_gx[W], col_gy[W], dirs[3 n]; out: n x C */
__kernel void irradiance_brute(__global const float *L, int W, int H, int C, __global const lx_irr_real *geo,
                               uint n, __global lx_irr_real *out)
{
    uint o = get_global_id(0);
    if (o >= n) return;
    __global const lx_irr_real *row_s2 = geo;
    __global const lx_irr_real *row_sc = geo + H;
    __global const lx_irr_real *col_gx = geo + 2 * H;
    __global const lx_irr_real *col_gy = geo + 2 * H + W;
    __global const lx_irr_real *dirs = geo + 2 * H + 2 * W;
    lx_irr_real nx = dirs[3 * o], ny = dirs[3 * o + 1], nz = dirs[3 * o + 2];
    lx_irr_real e0 = 0, e1 = 0, e2 = 0;
    for (int j = 0; j < H; j++) {
        lx_irr_real a = row_s2[j], b = nz * row_sc[j];
        __global const float *row = L + (size_t)j * W * C;
        lx_irr_real r0 = 0, r1 = 0, r2 = 0;
        if (C == 3) {
            for (int i = 0; i < W; i++) {
                lx_irr_real v = fmax(a * (nx * col_gx[i] + ny * col_gy[i]) + b, (lx_irr_real)0);
                r0 += v * (lx_irr_real)row[3 * i];
                r1 += v * (lx_irr_real)row[3 * i + 1];
                r2 += v * (lx_irr_real)row[3 * i + 2];
            }
        } else {
            for (int i = 0; i < W; i++) {
                lx_irr_real v = fmax(a * (nx * col_gx[i] + ny * col_gy[i]) + b, (lx_irr_real)0);
                r0 += v * (lx_irr_real)row[i];
            }
        }
        e0 += r0;
        e1 += r1;
        e2 += r2;
    }
    out[(size_t)o * C] = e0;
    if (C == 3) {
        out[(size_t)o * C + 1] = e1;
        out[(size_t)o * C + 2] = e2;
    }
}
