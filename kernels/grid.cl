/* grid.cl - illuminance on P points from M luminaires (point model) with the cosine-indexed
 * intensity table: row sqrt(1 - |cos g|), column the diamond angle of C, so no acos or atan2 in
 * the loop. One work-item per point. CPU twin: lx__table_eval (src/lighting/grid_private.h) and
 * pair_point (src/lighting/grid.c), and their SIMD twins in src/lighting/grid_simd.c.
 * Luminaire records of 16 reals: pos[3], ex[3], ey[3], ez[3], scale, cols, ns, table offset. */

#define LX_GRID_KERNEL(NAME, R, R3, SQRT)                                                              \
__kernel void NAME(__global const R *pts, __global const R *nrm, uint shared_normal,                   \
                   __global const R *lum, uint m, __global const float *tab,                           \
                   __global R *E, uint n)                                                              \
{                                                                                                      \
    uint i = get_global_id(0);                                                                         \
    if (i >= n) return;                                                                                \
    R px = pts[i], py = pts[n + i], pz = pts[2 * n + i];                                               \
    uint nn = shared_normal ? 1 : n, ni = shared_normal ? 0 : i;                                       \
    R nx = nrm[ni], ny = nrm[nn + ni], nz = nrm[2 * nn + ni];                                          \
    R e = 0;                                                                                           \
    for (uint k = 0; k < m; k++) {                                                                     \
        __global const R *L = lum + 16 * k;                                                            \
        R wx = px - L[0], wy = py - L[1], wz = pz - L[2];                                              \
        R d2 = wx * wx + wy * wy + wz * wz;                                                            \
        R cx = -(wx * nx + wy * ny + wz * nz);                                                         \
        if (!(d2 > 0) || cx <= 0) continue;                                                            \
        R d = SQRT(d2);                                                                                \
        R x = wx * L[3] + wy * L[4] + wz * L[5];                                                       \
        R y = wx * L[6] + wy * L[7] + wz * L[8];                                                       \
        R z = wx * L[9] + wy * L[10] + wz * L[11];                                                     \
        int cols = (int)L[13], ns = (int)L[14];                                                        \
        __global const float *T = tab + (ulong)L[15];                                                  \
        int h = z > 0;                                                                                 \
        R t = fmin((R)ns, (R)ns * SQRT((x * x + y * y) / (d * (d + fabs(z)))));                        \
        int r = min((int)t, ns - 1);                                                                   \
        R fr = t - (R)r;                                                                               \
        __global const float *row = T + (h * (ns + 1) + r) * cols;                                     \
        R I;                                                                                           \
        if (cols == 1) {                                                                               \
            I = (R)row[0] + fr * ((R)row[1] - (R)row[0]);                                              \
        } else {                                                                                       \
            R ax = fabs(x), ay = fabs(y), s = ax + ay, q = 0;                                          \
            if (s > 0) {                                                                               \
                if (y >= 0) q = x >= 0 ? y / s : 1 + ax / s;                                           \
                else q = x < 0 ? 2 + ay / s : 3 + ax / s;                                              \
            }                                                                                          \
            R tc = q * (R)((cols - 1) / 4);                                                            \
            int c = min((int)tc, cols - 2);                                                            \
            R fc = tc - (R)c;                                                                          \
            __global const float *a = row + c, *b = row + cols + c;                                    \
            R va = (R)a[0] + fc * ((R)a[1] - (R)a[0]);                                                 \
            R vb = (R)b[0] + fc * ((R)b[1] - (R)b[0]);                                                 \
            I = va + fr * (vb - va);                                                                   \
        }                                                                                              \
        e += L[12] * I * cx / (d2 * d);                                                                \
    }                                                                                                  \
    E[i] = e;                                                                                          \
}

LX_GRID_KERNEL(lx_grid_f32, float, float3, sqrt)

#if LX_FP64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
LX_GRID_KERNEL(lx_grid_f64, double, double3, sqrt)
#endif
