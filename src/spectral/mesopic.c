/* mesopic.c - CIE 191:2010 recommended system for mesopic photometry (MES2): mesopic luminance
 * from photopic and scotopic luminance with the adaptation coefficient m, solved iteratively. */
#include "spectral/spectral_private.h"

#include <math.h>

#define MES_A 0.7670          /* CIE 191:2010 eq. (3): m = a + b log10(L_mes) */
#define MES_B 0.3334
#define V0 (683.0 / 1699.0)   /* V'(lambda0) at 555 nm as CIE 191 writes it */
#define LP_HIGH 5.0           /* cd/m2: at and above, photopic (m = 1) */

static double lmes_of(double m, double lp, double ls)
{
    return (m * lp + (1.0 - m) * ls * V0) / (m + (1.0 - m) * V0);
}

static double m_of(double lmes)
{
    if (!(lmes > 0)) return 0.0;
    double m = MES_A + MES_B * log10(lmes);
    return m < 0 ? 0.0 : m > 1 ? 1.0 : m;
}

lx_status lx_mesopic_luminance(lx_ctx *ctx, double lp, double ls, double *lmes_out, double *m_out)
{
    LX__NEED_CTX(ctx);
    if (!isfinite(lp) || !isfinite(ls) || lp < 0 || ls < 0)
        return lx__error(ctx, LX_EINVAL, NULL, 0,
                         "mesopic: photopic (%g) and scotopic (%g) luminances must be finite and >= 0", lp, ls);
    if (!lmes_out) return lx__error(ctx, LX_EINVAL, NULL, 0, "mesopic: output is NULL");
    double m, lmes;
    if (lp >= LP_HIGH) {
        m = 1.0, lmes = lp;
    } else {
        /* the standard's iteration: m0 = 0.5, L_mes,n from m_(n-1), m_n from L_mes,n */
        m = 0.5;
        int done = 0;
        for (int it = 0; it < 200; it++) {
            double mn = m_of(lmes_of(m, lp, ls));
            if (fabs(mn - m) < 1e-13) {
                m = mn, done = 1;
                break;
            }
            m = mn;
        }
        if (!done) {
            /* g(m) = m_of(L_mes(m)) - m is >= 0 at m = 0 and <= 0 at m = 1: bisect */
            double a = 0.0, b = 1.0;
            for (int it = 0; it < 200 && b - a > 1e-15; it++) {
                double c = 0.5 * (a + b);
                if (m_of(lmes_of(c, lp, ls)) - c > 0) a = c;
                else b = c;
            }
            m = 0.5 * (a + b);
        }
        lmes = lmes_of(m, lp, ls);
    }
    *lmes_out = lmes;
    if (m_out) *m_out = m;
    return LX_OK;
}
