/* test_api.c - the conventions the public header (src/luxcalc.h) states for every function, checked
 * function by function: a NULL context is LX_EINVAL and nothing is read or written (outputs keep
 * their sentinels, no file appears, no callback runs); the functions that accept a NULL context do
 * what the header says; every context-taking function of the header has its case here (the header
 * is read at run time, so a new function cannot skip the rule); creating functions set *out to NULL
 * when they fail; options with non-zero reserved space are refused; results write their reserved
 * space as zero; the header's version macros equal lx_version(). */
#include "lx_test.h"

#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- fixtures: valid arguments, made with a real context ---- */

static lx_ctx *C;           /* the real context the fixtures were made with */
static lx_spd D65;          /* a view of the embedded D65 table */
static lx_luminaire *LUM;   /* a 1000 lm isotropic model */
static lx_envmap *MAP;      /* 8 x 4, one channel, 1.0 everywhere */
static lx_scene *SCENE;     /* tests/data/scenes/point.scene from memory */
static lx_scene_plan *PLAN;
static char DIR_[64];       /* a temporary directory for the writers */
static const char *SPD_FILE = "samples/spd/cie_illuminants.csv";
static const char *IES_FILE = "samples/ies/point_isotropic_1000lm.ies";
static const char *EXR_FILE = "samples/envmaps/furnace.exr";
static const char *BATCH_FILE = "samples/spd/led_batch.csv";
static const char *SCENE_TEXT = "[luminaire lamp]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 400 cd\n"
                                "[receiver floor]\ntype = point\nposition = 0 m, 0 m, 0 m\n";
static const char *SPD_TEXT = "wavelength,a\n500,1\n600,2\n";
static const double SENT = 12345.678; /* what outputs hold before a call that must not write them */
static void *const PSENT = (void *)&SENT;

static int setup(void **state)
{
    (void)state;
    if (lx_ctx_create(&C)) return -1;
    lx_lum_model m = {.kind = LX_LUM_MODEL_POINT, .flux_lm = 1000};
    if (lx_illuminant_get(C, "D65", &D65) || lx_luminaire_from_model(C, &m, &LUM) ||
        lx_envmap_create(C, 8, 4, 1, &MAP) ||
        lx_scene_read_mem(C, "tests/data/scenes/api.scene", SCENE_TEXT, strlen(SCENE_TEXT), &SCENE) ||
        lx_scene_plan_make(C, SCENE, LX_BACKEND_CPU, &PLAN)) {
        fprintf(stderr, "fixtures: %s\n", lx_ctx_errmsg(C));
        return -1;
    }
    for (int i = 0; i < 32; i++) MAP->data[i] = 1.0f;
    snprintf(DIR_, sizeof DIR_, "%s/lxapiXXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    return mkdtemp(DIR_) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    lx_scene_plan_free(PLAN);
    lx_scene_free(SCENE);
    lx_envmap_free(MAP);
    lx_luminaire_free(LUM);
    lx_ctx_destroy(C);
    rmdir(DIR_);
    return 0;
}

/* a path in the temporary directory that must not exist after the call */
static const char *out_path(const char *name)
{
    static char p[128];
    snprintf(p, sizeof p, "%s/%s", DIR_, name);
    return p;
}
static void assert_absent(const char *path) { assert_int_not_equal(access(path, F_OK), 0); }

#define NUL LX_EINVAL
#define EXPECT_EINVAL(call) assert_int_equal((call), NUL)

/* ---- the cases: one per context-taking function of the header ---- */

static void t_lx_ctx_create(void) { EXPECT_EINVAL(lx_ctx_create(NULL)); } /* its NULL is the out pointer */
static void t_lx_ctx_destroy(void) { lx_ctx_destroy(NULL); }              /* accepts NULL */
static void t_lx_ctx_errmsg(void) { assert_string_equal(lx_ctx_errmsg(NULL), ""); }
static void t_lx_ctx_errfile(void) { assert_null(lx_ctx_errfile(NULL)); }
static void t_lx_ctx_errline(void) { assert_int_equal(lx_ctx_errline(NULL), 0); }
static void t_lx_ctx_set_log(void) { lx_ctx_set_log(NULL, NULL, NULL, LX_LOG_DEBUG); } /* a no-op */
static void t_lx_ctx_backend_used(void) { assert_int_equal(lx_ctx_backend_used(NULL), LX_BACKEND_AUTO); }
static void t_lx_cl_ready(void) { assert_int_equal(lx_cl_ready(NULL), 0); }
static void t_lx_ctx_counters(void)
{
    lx_counters c;
    memset(&c, 0xab, sizeof c);
    lx_ctx_counters(NULL, &c);
    lx_counters z;
    memset(&z, 0, sizeof z);
    assert_memory_equal(&c, &z, sizeof c);
}
static void t_lx_ctx_counters_reset(void) { lx_ctx_counters_reset(NULL); }

static void t_lx_backend_parse(void)
{
    lx_backend b = (lx_backend)77;
    EXPECT_EINVAL(lx_backend_parse(NULL, "cpu", &b));
    assert_int_equal(b, 77);
}
static void t_lx_simd_parse(void)
{
    lx_simd s = (lx_simd)77;
    EXPECT_EINVAL(lx_simd_parse(NULL, "scalar", &s));
    assert_int_equal(s, 77);
}
static void t_lx_cl_select(void) { EXPECT_EINVAL(lx_cl_select(NULL, -1, -1, LX_CL_AUTO)); }
static void t_lx_cl_borrow(void) { EXPECT_EINVAL(lx_cl_borrow(NULL, PSENT, PSENT)); } /* never dereferenced */
static void t_lx_cl_devices(void)
{
    lx_cl_device_info *d = PSENT;
    size_t n = 77;
    EXPECT_EINVAL(lx_cl_devices(NULL, &d, &n));
    assert_ptr_equal(d, PSENT);
    assert_int_equal(n, 77);
}
static void t_lx_cl_info(void)
{
    lx_cl_device_info i;
    memset(&i, 0x5a, sizeof i);
    lx_cl_device_info j = i;
    EXPECT_EINVAL(lx_cl_info(NULL, &i));
    assert_memory_equal(&i, &j, sizeof i);
}

static void t_lx_function_get(void)
{
    lx_spd s = {.n = 77};
    EXPECT_EINVAL(lx_function_get(NULL, LX_FN_YBAR_2, &s));
    assert_int_equal(s.n, 77);
}
static void t_lx_illuminant_get(void)
{
    lx_spd s = {.n = 77};
    EXPECT_EINVAL(lx_illuminant_get(NULL, "D65", &s));
    assert_int_equal(s.n, 77);
}
static void t_lx_tcs_get(void)
{
    lx_spd s = {.n = 77};
    EXPECT_EINVAL(lx_tcs_get(NULL, 1, &s));
    assert_int_equal(s.n, 77);
}
static void t_lx_daylight(void)
{
    double l[2] = {500, 600}, v[2] = {SENT, SENT};
    EXPECT_EINVAL(lx_daylight(NULL, 6500, 2, l, v));
    assert_true(v[0] == SENT && v[1] == SENT);
}
static void t_lx_daylight_xy(void)
{
    double x = SENT, y = SENT;
    EXPECT_EINVAL(lx_daylight_xy(NULL, 6500, &x, &y));
    assert_true(x == SENT && y == SENT);
}

static void t_lx_spd_read_file(void)
{
    lx_spd_set *s = PSENT;
    EXPECT_EINVAL(lx_spd_read_file(NULL, SPD_FILE, &s));
    assert_ptr_equal(s, PSENT);
}
static void t_lx_spd_read_mem(void)
{
    lx_spd_set *s = PSENT;
    EXPECT_EINVAL(lx_spd_read_mem(NULL, "a.csv", SPD_TEXT, strlen(SPD_TEXT), &s));
    assert_ptr_equal(s, PSENT);
}
static void t_lx_spd_read_stream(void)
{
    lx_spd_set *s = PSENT;
    EXPECT_EINVAL(lx_spd_read_stream(NULL, "-", stdin, NULL, 0, NULL, &s));
    assert_ptr_equal(s, PSENT);
}
static void t_lx_file_open(void)
{
    FILE *f = PSENT;
    EXPECT_EINVAL(lx_file_open(NULL, BATCH_FILE, &f));
    assert_ptr_equal(f, PSENT);
}
static void t_lx_cct_from_uv_batch(void)
{
    double u = 0.1978, v = 0.3122, t = -1, d = -1;
    EXPECT_EINVAL(lx_cct_from_uv_batch(NULL, LX_OBSERVER_2, 1, &u, &v, &t, &d));
    assert_true(t == -1 && d == -1);
}
static void t_lx_spd_check(void) { EXPECT_EINVAL(lx_spd_check(NULL, &D65)); }
static void t_lx_spd_integrate(void)
{
    double v = SENT;
    EXPECT_EINVAL(lx_spd_integrate(NULL, &D65, &D65, LX_METHOD_AUTO, &v));
    assert_true(v == SENT);
}
static void t_lx_spd_integrate_radiant(void)
{
    double v = SENT;
    EXPECT_EINVAL(lx_spd_integrate_radiant(NULL, &D65, LX_METHOD_AUTO, &v));
    assert_true(v == SENT);
}
static void t_lx_spd_colorimetry(void) /* it segfaulted before 0.2.0 */
{
    lx_colorimetry c = {.X = SENT};
    EXPECT_EINVAL(lx_spd_colorimetry(NULL, &D65, LX_OBSERVER_2, LX_METHOD_AUTO, &c));
    assert_true(c.X == SENT);
}
static void t_lx_colorimetry_from_integrals(void)
{
    double xyz[3] = {1, 1, 1};
    lx_colorimetry c = {.X = SENT};
    EXPECT_EINVAL(lx_colorimetry_from_integrals(NULL, LX_OBSERVER_2, xyz, 1, 1, &c));
    assert_true(c.X == SENT);
}
static void t_lx_cct_from_uv(void)
{
    double t = SENT, d = SENT;
    EXPECT_EINVAL(lx_cct_from_uv(NULL, LX_OBSERVER_2, 0.1978, 0.3122, &t, &d));
    assert_true(t == SENT && d == SENT);
}
static void t_lx_cct_from_xy(void)
{
    double t = SENT, d = SENT;
    EXPECT_EINVAL(lx_cct_from_xy(NULL, LX_OBSERVER_2, 0.3127, 0.3290, &t, &d));
    assert_true(t == SENT && d == SENT);
}
static void t_lx_planck_uv(void)
{
    double u = SENT, v = SENT;
    EXPECT_EINVAL(lx_planck_uv(NULL, LX_OBSERVER_2, 3000, &u, &v));
    assert_true(u == SENT && v == SENT);
}

/* a 2 x 3 batch on 500, 510, 520 nm */
static const double BV[6] = {1, 2, 3, 4, 5, 6};
static const lx_batch BATCH = {.n_spectra = 2, .n_lambda = 3, .start_nm = 500, .step_nm = 10, .dtype = LX_F64, .values = BV};
static const lx_function FNS[2] = {LX_FN_YBAR_2, LX_FN_VPRIME};

static void t_lx_batch_integrate(void)
{
    double out[4] = {SENT, SENT, SENT, SENT};
    lx_batch_opts o = {.backend = LX_BACKEND_CPU};
    EXPECT_EINVAL(lx_batch_integrate(NULL, &BATCH, FNS, 2, &o, out));
    assert_true(out[0] == SENT && out[3] == SENT);
}
static void t_lx_batch_table_read(void)
{
    lx_batch_table *t = PSENT;
    EXPECT_EINVAL(lx_batch_table_read(NULL, BATCH_FILE, LX_F64, 1, &t));
    assert_ptr_equal(t, PSENT);
}
static void t_lx_batch_table_read_mem(void)
{
    const char *txt = "id,500,510\na,1,2\n";
    lx_batch_table *t = PSENT;
    EXPECT_EINVAL(lx_batch_table_read_mem(NULL, "m.csv", txt, strlen(txt), LX_F64, 1, &t));
    assert_ptr_equal(t, PSENT);
}
static lx_status count_chunk(void *user, const lx_batch_table *chunk, size_t row0)
{
    (void)chunk, (void)row0;
    ++*(int *)user;
    return LX_OK;
}
static void t_lx_batch_table_stream(void)
{
    int calls = 0;
    EXPECT_EINVAL(lx_batch_table_stream(NULL, BATCH_FILE, LX_F64, 1, count_chunk, &calls));
    assert_int_equal(calls, 0);
}
static lx_status emit_count(void *user, const lx_batch_table *chunk, size_t row0, void *state)
{
    (void)chunk, (void)row0, (void)state;
    ++*(int *)user;
    return LX_OK;
}
static void t_lx_batch_table_stream_ex(void)
{
    int calls = 0;
    lx_batch_stream cb = {.user = &calls, .emit = emit_count};
    EXPECT_EINVAL(lx_batch_table_stream_ex(NULL, BATCH_FILE, LX_F64, 1, &cb));
    assert_int_equal(calls, 0);
}
static void t_lx_batch_table_integrate_file(void)
{
    double *r = PSENT;
    size_t n = 77;
    EXPECT_EINVAL(lx_batch_table_integrate_file(NULL, BATCH_FILE, FNS, 2, 1, &r, &n));
    assert_ptr_equal(r, PSENT);
    assert_int_equal(n, 77);
}
static void t_lx_batch_resample(void)
{
    const double lam[3] = {500, 510, 520}, val[3] = {1, 2, 3};
    const size_t off[1] = {0}, nin[1] = {3};
    double dv[3] = {SENT, SENT, SENT};
    lx_batch dst = {.n_spectra = 77, .n_lambda = 3, .start_nm = 500, .step_nm = 10, .dtype = LX_F64, .values = dv};
    EXPECT_EINVAL(lx_batch_resample(NULL, 1, lam, val, off, nin, &dst, NULL));
    assert_true(dv[0] == SENT && dst.n_spectra == 77);
}
static void t_lx_batch_colorimetry(void)
{
    lx_colorimetry c[2] = {{.X = SENT}, {.X = SENT}};
    EXPECT_EINVAL(lx_batch_colorimetry(NULL, &BATCH, LX_OBSERVER_2, NULL, c));
    assert_true(c[0].X == SENT && c[1].X == SENT);
}
static void t_lx_alphaopic_compute(void)
{
    lx_alphaopic a = {.illuminance = SENT};
    EXPECT_EINVAL(lx_alphaopic_compute(NULL, &D65, LX_METHOD_AUTO, &a));
    assert_true(a.illuminance == SENT);
}
static void t_lx_alphaopic_batch(void)
{
    double out[12];
    for (int i = 0; i < 12; i++) out[i] = SENT;
    EXPECT_EINVAL(lx_alphaopic_batch(NULL, &BATCH, NULL, out));
    assert_true(out[0] == SENT && out[11] == SENT);
}
static void t_lx_mesopic_luminance(void)
{
    double l = SENT, m = SENT;
    EXPECT_EINVAL(lx_mesopic_luminance(NULL, 1, 1, &l, &m));
    assert_true(l == SENT && m == SENT);
}
static void t_lx_efficacy_from_spd_file(void)
{
    double k = SENT;
    EXPECT_EINVAL(lx_efficacy_from_spd_file(NULL, "samples/spd/laser_532nm.csv", &k));
    assert_true(k == SENT);
}
static void t_lx_cri_compute(void)
{
    lx_cri r = {.ra = SENT};
    EXPECT_EINVAL(lx_cri_compute(NULL, &D65, &r));
    assert_true(r.ra == SENT);
}
static void t_lx_tm30_compute(void)
{
    static lx_tm30 t;
    t.rf = SENT;
    EXPECT_EINVAL(lx_tm30_compute(NULL, &D65, &t));
    assert_true(t.rf == SENT);
}

static void t_lx_unc_model_create(void)
{
    lx_unc_model *m = PSENT;
    EXPECT_EINVAL(lx_unc_model_create(NULL, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_unc_model_add(void)
{
    lx_unc_model *m = NULL;
    assert_int_equal(lx_unc_model_create(C, &m), LX_OK);
    lx_unc_component c = {.kind = LX_UNC_SCALE, .sigma = 0.01};
    EXPECT_EINVAL(lx_unc_model_add(NULL, m, &c));
    assert_int_equal(lx_unc_model_count(m), 0);
    lx_unc_model_free(m);
}
static void t_lx_unc_model_parse(void)
{
    lx_unc_model *m = PSENT;
    EXPECT_EINVAL(lx_unc_model_parse(NULL, "1%", NULL, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_spd_uncertainty(void)
{
    lx_unc_model *m = NULL;
    assert_int_equal(lx_unc_model_parse(C, "1%", NULL, &m), LX_OK);
    lx_unc_result *r = PSENT;
    EXPECT_EINVAL(lx_spd_uncertainty(NULL, &D65, m, NULL, &r));
    assert_ptr_equal(r, PSENT);
    lx_unc_model_free(m);
}

static void t_lx_unit_find(void)
{
    const lx_unit *u = PSENT;
    EXPECT_EINVAL(lx_unit_find(NULL, "lx", &u));
    assert_ptr_equal(u, PSENT);
}
static void t_lx_quantity_parse(void)
{
    double v = SENT;
    lx_quantity q = (lx_quantity)77;
    EXPECT_EINVAL(lx_quantity_parse(NULL, "46 fc", LX_Q_ILLUMINANCE, NULL, &v, &q));
    assert_true(v == SENT && q == 77);
}
static void t_lx_unit_convert(void)
{
    double v = SENT;
    EXPECT_EINVAL(lx_unit_convert(NULL, 1, "fc", "lx", &v));
    assert_true(v == SENT);
}
static void t_lx_unit_format(void)
{
    char buf[32] = "untouched";
    EXPECT_EINVAL(lx_unit_format(NULL, 1, "lx", buf, sizeof buf));
    assert_string_equal(buf, "untouched");
}
static void t_lx_radiometric_convert(void)
{
    double v = SENT;
    lx_quantity q = (lx_quantity)77;
    EXPECT_EINVAL(lx_radiometric_convert(NULL, 1, LX_Q_RADIANT_FLUX, 683, &v, &q));
    assert_true(v == SENT && q == 77);
}

/* sources, inverse problems, solid angles: one double output each */
#define ONE_OUT(name, ...)                                                                                   \
    static void t_##name(void)                                                                               \
    {                                                                                                        \
        double v = SENT;                                                                                     \
        EXPECT_EINVAL(name(NULL, __VA_ARGS__, &v));                                                          \
        assert_true(v == SENT);                                                                              \
    }
ONE_OUT(lx_point_illuminance, 100, 2, 0)
ONE_OUT(lx_point_intensity, 1000)
ONE_OUT(lx_warn_exponent_from_beam, 0.5)
ONE_OUT(lx_warn_beam_from_exponent, 10)
ONE_OUT(lx_lambertian_luminance, 0.5, 100)
ONE_OUT(lx_solve_distance, 100, 400, 0)
ONE_OUT(lx_solve_intensity, 100, 2, 0)
ONE_OUT(lx_solve_flux, 100, 2, 0, 10, 0)
ONE_OUT(lx_solid_angle_cap, 0.5)
ONE_OUT(lx_solid_angle_latlong_pixel, 8, 4, 1)
ONE_OUT(lx_solid_angle_rect, -1, 1, -1, 1, 2)
static void t_lx_warn_intensity(void)
{
    double p = SENT, i = SENT;
    EXPECT_EINVAL(lx_warn_intensity(NULL, 1000, 10, 0.1, &p, &i));
    assert_true(p == SENT && i == SENT);
}
static void t_lx_disk_illuminance(void)
{
    lx_source_result r = {.illuminance_lx = SENT};
    EXPECT_EINVAL(lx_disk_illuminance(NULL, 1000, 0.5, 1, 0, LX_MODEL_AUTO, &r));
    assert_true(r.illuminance_lx == SENT);
}
static void t_lx_rect_illuminance(void)
{
    lx_source_result r = {.illuminance_lx = SENT};
    EXPECT_EINVAL(lx_rect_illuminance(NULL, 1000, 1, 2, 2, 0, 0, LX_MODEL_AUTO, &r));
    assert_true(r.illuminance_lx == SENT);
}

static void t_lx_luminaire_read_file(void)
{
    lx_luminaire *l = PSENT;
    EXPECT_EINVAL(lx_luminaire_read_file(NULL, IES_FILE, &l));
    assert_ptr_equal(l, PSENT);
}
static void t_lx_luminaire_read_mem(void)
{
    const char *txt = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 1 1 2 0 0 0\n1 1 0\n0 90 180\n0\n1 1 1\n";
    lx_luminaire *l = PSENT;
    EXPECT_EINVAL(lx_luminaire_read_mem(NULL, "m.ies", txt, strlen(txt), &l));
    assert_ptr_equal(l, PSENT);
}
static void t_lx_luminaire_summary(void)
{
    lx_lum_summary s = {.lumens = SENT};
    EXPECT_EINVAL(lx_luminaire_summary(NULL, LUM, &s));
    assert_true(s.lumens == SENT);
}
static void t_lx_luminaire_from_model(void)
{
    lx_lum_model m = {.kind = LX_LUM_MODEL_POINT, .flux_lm = 1000};
    lx_luminaire *l = PSENT;
    EXPECT_EINVAL(lx_luminaire_from_model(NULL, &m, &l));
    assert_ptr_equal(l, PSENT);
}
static void t_lx_luminaire_write_ies(void)
{
    char *t = PSENT;
    size_t n = 77;
    EXPECT_EINVAL(lx_luminaire_write_ies(NULL, LUM, &t, &n));
    assert_ptr_equal(t, PSENT);
    assert_int_equal(n, 77);
}
static void t_lx_plane_axis(void)
{
    lx_plane p = {.na = 77};
    EXPECT_EINVAL(lx_plane_axis(NULL, 'z', 0, 0, 1, 0, 1, 0.5, 0, 0, &p));
    assert_int_equal(p.na, 77);
}
static void t_lx_plane_cells(void)
{
    lx_plane p = {.na = 77};
    EXPECT_EINVAL(lx_plane_cells(NULL, 'z', 0, 0, 1, 0, 1, 0.5, 0, 0, &p));
    assert_int_equal(p.na, 77);
}
static const lx_plane PLANE = {.u = {1, 0, 0}, .v = {0, 1, 0}, .a1 = 1, .b1 = 1, .na = 2, .nb = 2, .normal = {0, 0, 1}};
static void t_lx_grid_illuminance(void)
{
    lx_placement pl = {.lum = NULL, .pos_m = {0, 0, 2}, .aim = {0, 0, -1}};
    pl.lum = LUM;
    const double pts[3] = {0, 0, 0}, up[3] = {0, 0, 1};
    double E = SENT;
    EXPECT_EINVAL(lx_grid_illuminance(NULL, &pl, 1, pts, 1, up, 1, NULL, &E));
    assert_true(E == SENT);
}
static void t_lx_plane_points(void)
{
    double *p = PSENT;
    size_t n = 77;
    EXPECT_EINVAL(lx_plane_points(NULL, &PLANE, &p, &n));
    assert_ptr_equal(p, PSENT);
    assert_int_equal(n, 77);
}
static void t_lx_grid_stats_compute(void)
{
    const double E[2] = {1, 2};
    lx_grid_stats s = {.avg = SENT};
    EXPECT_EINVAL(lx_grid_stats_compute(NULL, E, 2, &s));
    assert_true(s.avg == SENT);
}

static void t_lx_envmap_create_cube(void)
{
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_envmap_create_cube(NULL, 4, 1, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_envmap_create(void)
{
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_envmap_create(NULL, 8, 4, 1, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_envmap_luminance(void)
{
    double L[32];
    for (int i = 0; i < 32; i++) L[i] = SENT;
    EXPECT_EINVAL(lx_envmap_luminance(NULL, MAP, L));
    assert_true(L[0] == SENT && L[31] == SENT);
}
static void t_lx_envmap_downsample(void)
{
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_envmap_downsample(NULL, MAP, 4, 2, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_rgb_y_weights(void)
{
    const double xy[8] = {0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290};
    double w[3] = {SENT, SENT, SENT};
    EXPECT_EINVAL(lx_rgb_y_weights(NULL, xy, w));
    assert_true(w[0] == SENT && w[2] == SENT);
}
static void t_lx_exr_read(void)
{
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_exr_read(NULL, EXR_FILE, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_exr_read_any(void)
{
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_exr_read_any(NULL, EXR_FILE, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_envmap_write_exr(void)
{
    const char *p = out_path("map.exr");
    EXPECT_EINVAL(lx_envmap_write_exr(NULL, p, MAP, NULL));
    assert_absent(p);
}
static void t_lx_sh9_project(void)
{
    lx_sh9 sh = {.channels = 77};
    EXPECT_EINVAL(lx_sh9_project(NULL, MAP, &sh));
    assert_int_equal(sh.channels, 77);
}
static void t_lx_sh9_irradiance(void)
{
    lx_sh9 sh = {.channels = 1, .c = {{1}}};
    const double n[3] = {0, 0, 1};
    double E = SENT;
    EXPECT_EINVAL(lx_sh9_irradiance(NULL, &sh, LX_SH9_WINDOW_NONE, n, &E));
    assert_true(E == SENT);
}
static void t_lx_irradiance_dirs(void)
{
    const double n[3] = {0, 0, 1};
    double E = SENT;
    EXPECT_EINVAL(lx_irradiance_dirs(NULL, MAP, 1, n, NULL, &E));
    assert_true(E == SENT);
}
static void t_lx_irradiance_map(void)
{
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_irradiance_map(NULL, MAP, 0, 0, NULL, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_spectral_exr_read_xyz(void)
{
    lx_xyz_image *i = PSENT;
    EXPECT_EINVAL(lx_spectral_exr_read_xyz(NULL, EXR_FILE, LX_OBSERVER_2, NULL, &i));
    assert_ptr_equal(i, PSENT);
}
/* a one-pixel image, as lx_spectral_exr_read_xyz makes them (the writers only read it) */
static double IMG_XYZ[3] = {95.047, 100, 108.883}, IMG_LAM[2] = {500, 600};
static const lx_xyz_image IMG = {.width = 1, .height = 1, .xyz = IMG_XYZ, .n_lambda = 2, .lambda_nm = IMG_LAM};
static void t_lx_xyz_image_write_exr(void)
{
    const char *p = out_path("xyz.exr");
    EXPECT_EINVAL(lx_xyz_image_write_exr(NULL, p, &IMG));
    assert_absent(p);
}

static void t_lx_scene_read_file(void)
{
    lx_scene *s = PSENT;
    EXPECT_EINVAL(lx_scene_read_file(NULL, "tests/data/scenes/point.scene", &s));
    assert_ptr_equal(s, PSENT);
}
static void t_lx_scene_read_mem(void)
{
    lx_scene *s = PSENT;
    EXPECT_EINVAL(lx_scene_read_mem(NULL, "m.scene", SCENE_TEXT, strlen(SCENE_TEXT), &s));
    assert_ptr_equal(s, PSENT);
}
static void t_lx_scene_plan_make(void)
{
    lx_scene_plan *p = PSENT;
    EXPECT_EINVAL(lx_scene_plan_make(NULL, SCENE, LX_BACKEND_CPU, &p));
    assert_ptr_equal(p, PSENT);
}
static void t_lx_scene_eval(void)
{
    lx_scene_result *r = PSENT;
    EXPECT_EINVAL(lx_scene_eval(NULL, SCENE, PLAN, NULL, &r));
    assert_ptr_equal(r, PSENT);
}
static void t_lx_scene_plan_make_mode(void)
{
    lx_scene_plan *p = PSENT;
    EXPECT_EINVAL(lx_scene_plan_make_mode(NULL, SCENE, LX_BACKEND_CPU, LX_SCENE_EMERGENCY, &p));
    assert_ptr_equal(p, PSENT);
}
static void t_lx_en12464_grid_size(void)
{
    lx_en12464_grid g;
    memset(&g, 0xcd, sizeof g);
    unsigned char before[sizeof g];
    memcpy(before, &g, sizeof g);
    EXPECT_EINVAL(lx_en12464_grid_size(NULL, 5, 4, LX_GRID_ROUND_NEAREST, &g));
    assert_memory_equal(&g, before, sizeof g);
}
static void t_lx_scene_area_stats(void)
{
    lx_area_stats s;
    memset(&s, 0xcd, sizeof s);
    unsigned char before[sizeof s];
    memcpy(before, &s, sizeof s);
    lx_scene_result *r = NULL;
    assert_int_equal(lx_scene_eval(C, SCENE, PLAN, NULL, &r), LX_OK);
    EXPECT_EINVAL(lx_scene_area_stats(NULL, SCENE, r, 0, &s));
    assert_memory_equal(&s, before, sizeof s);
    lx_scene_result_free(r);
}
static void t_lx_leni_compute(void)
{
    lx_leni_input in = {.area_m2 = 10, .power_W = 100, .night_h = 100, .constant_factor = 1, .occupancy_factor = 1,
                        .daylight_factor = 1};
    lx_leni e;
    memset(&e, 0xcd, sizeof e);
    unsigned char before[sizeof e];
    memcpy(before, &e, sizeof e);
    EXPECT_EINVAL(lx_leni_compute(NULL, &in, &e));
    assert_memory_equal(&e, before, sizeof e);
}
static void t_lx_scene_energy(void)
{
    lx_leni_input in;
    lx_leni e;
    EXPECT_EINVAL(lx_scene_energy(NULL, SCENE, &in, &e));
}
static void t_lx_scene_check(void)
{
    lx_scene_checks *k = PSENT;
    lx_scene_result *r = NULL;
    assert_int_equal(lx_scene_eval(C, SCENE, PLAN, NULL, &r), LX_OK);
    EXPECT_EINVAL(lx_scene_check(NULL, SCENE, r, NULL, NULL, &k));
    assert_ptr_equal(k, PSENT);
    lx_scene_result_free(r);
}

/* plots: nothing may appear at the path */
static void t_lx_falsecolor_write_png(void)
{
    const char *p = out_path("f.png");
    const double v[4] = {1, 2, 3, 4};
    EXPECT_EINVAL(lx_falsecolor_write_png(NULL, p, 2, 2, v, NULL));
    assert_absent(p);
}
static void t_lx_envmap_preview_write_png(void)
{
    const char *p = out_path("p.png");
    const lx_envmap *maps[1] = {MAP};
    EXPECT_EINVAL(lx_envmap_preview_write_png(NULL, p, 1, maps, NULL));
    assert_absent(p);
}
static void t_lx_irradiance_write_png(void)
{
    const char *p = out_path("i.png");
    EXPECT_EINVAL(lx_irradiance_write_png(NULL, p, MAP, MAP, "sh9", LX_PLOT_SCALE_LOG));
    assert_absent(p);
}
static void t_lx_spd_report_write_png(void)
{
    const char *p = out_path("r.png");
    EXPECT_EINVAL(lx_spd_report_write_png(NULL, &D65, NULL, p));
    assert_absent(p);
}
static void t_lx_tm30_report_write_png(void)
{
    const char *p = out_path("t.png");
    EXPECT_EINVAL(lx_tm30_report_write_png(NULL, &D65, NULL, p));
    assert_absent(p);
}
static void t_lx_xyz_image_write_png(void)
{
    const char *p = out_path("x.png");
    EXPECT_EINVAL(lx_xyz_image_write_png(NULL, p, &IMG));
    assert_absent(p);
}
static void t_lx_grid_write_png(void)
{
    const char *p = out_path("g.png");
    const double E[4] = {1, 2, 3, 4};
    EXPECT_EINVAL(lx_grid_write_png(NULL, p, &PLANE, E, NULL));
    assert_absent(p);
}
static void t_lx_scene_report_write_pdf(void)
{
    const char *p = out_path("r.pdf");
    EXPECT_EINVAL(lx_scene_report_write_pdf(NULL, SCENE, NULL, p));
    assert_absent(p);
}
static void t_lx_scene_outlines(void)
{
    lx_plot_outline *o = PSENT;
    size_t n = 7;
    EXPECT_EINVAL(lx_scene_outlines(NULL, SCENE, &PLANE, &o, &n));
    assert_true(o == PSENT && n == 7);
}
static void t_lx_scene_receiver_plane(void)
{
    lx_plane p, ref;
    memset(&p, 0xab, sizeof p);
    ref = p;
    EXPECT_EINVAL(lx_scene_receiver_plane(NULL, SCENE, 0, &p));
    assert_memory_equal(&p, &ref, sizeof p);
}
static void t_lx_scene_receiver_write_png(void)
{
    const char *p = out_path("r.png");
    EXPECT_EINVAL(lx_scene_receiver_write_png(NULL, p, SCENE, NULL, 0, NULL));
    assert_absent(p);
}
static void t_lx_error_time_write_png(void)
{
    const char *p = out_path("e.png");
    const lx_plot_point pts[2] = {{1e-3, 1e-6, "A", 0}, {1e-2, 1e-9, "B", 0}};
    const char *names[1] = {"s"};
    EXPECT_EINVAL(lx_error_time_write_png(NULL, p, "t", "x", "y", 2, pts, 1, names));
    assert_absent(p);
}

/* input limits, checks of results */
static void t_lx_ctx_set_input_limit(void) { EXPECT_EINVAL(lx_ctx_set_input_limit(NULL, LX_INPUT_SPECTRUM, 1 << 20)); }
static void t_lx_ctx_input_limit(void) /* accepts NULL: the default */
{
    assert_int_equal(lx_ctx_input_limit(NULL, LX_INPUT_SPECTRUM), (size_t)256 << 20);
}
static void t_lx_colorimetry_check(void)
{
    lx_colorimetry r;
    memset(&r, 0, sizeof r);
    EXPECT_EINVAL(lx_colorimetry_check(NULL, &r, 0));
}

/* glare, skies and the sun: outputs keep their sentinels */
static void t_lx_ugr(void)
{
    const double L[1] = {1e4}, w[1] = {1e-3}, p[1] = {1};
    double terms[1] = {SENT}, u = SENT;
    EXPECT_EINVAL(lx_ugr(NULL, 10, 1, L, w, p, terms, &u));
    assert_true(u == SENT && terms[0] == SENT);
}
static void t_lx_ugr_table_compute(void)
{
    lx_ugr_table *t = malloc(sizeof *t);
    memset(t, 0xab, sizeof *t);
    lx_ugr_table ref = *t;
    EXPECT_EINVAL(lx_ugr_table_compute(NULL, LUM, t));
    assert_memory_equal(t, &ref, sizeof ref);
    free(t);
}
static void t_lx_dominant_wavelength(void)
{
    lx_dominant d, ref;
    memset(&d, 0xab, sizeof d);
    ref = d;
    EXPECT_EINVAL(lx_dominant_wavelength(NULL, LX_OBSERVER_2, 0.5, 0.4, 1.0 / 3, 1.0 / 3, &d));
    assert_memory_equal(&d, &ref, sizeof d);
}
static void t_lx_spd_shape_compute(void)
{
    lx_spd_shape sh, ref;
    memset(&sh, 0xab, sizeof sh);
    ref = sh;
    EXPECT_EINVAL(lx_spd_shape_compute(NULL, &D65, &sh));
    assert_memory_equal(&sh, &ref, sizeof sh);
}
static void t_lx_ugr_table_text(void)
{
    lx_ugr_table t;
    memset(&t, 0, sizeof t);
    char *text = PSENT;
    EXPECT_EINVAL(lx_ugr_table_text(NULL, &t, &text));
    assert_true(text == PSENT);
}
static void t_lx_sky_cie(void)
{
    const double sun[3] = {0, 0.5, 0.8};
    lx_sky s, ref;
    memset(&s, 0xab, sizeof s);
    ref = s;
    EXPECT_EINVAL(lx_sky_cie(NULL, 12, sun, LX_SKY_BY_ZENITH, 5000, &s));
    assert_memory_equal(&s, &ref, sizeof s);
}
static void t_lx_sky_cie_params(void)
{
    double p[5] = {SENT, SENT, SENT, SENT, SENT};
    EXPECT_EINVAL(lx_sky_cie_params(NULL, 12, p));
    assert_true(p[0] == SENT && p[4] == SENT);
}
static void t_lx_sky_perez(void)
{
    lx_perez_input in = {.sun_dir = {0, 0.5, 0.8}, .direct_normal_W_m2 = 500, .diffuse_horizontal_W_m2 = 100,
                         .day_of_year = 172};
    lx_sky s, ref;
    memset(&s, 0xab, sizeof s);
    ref = s;
    EXPECT_EINVAL(lx_sky_perez(NULL, &in, &s));
    assert_memory_equal(&s, &ref, sizeof s);
}
static void t_lx_sky_illuminance(void)
{
    lx_sky s;
    const double sun[3] = {0, 0.5, 0.8}, up[3] = {0, 0, 1};
    lx_assert_ok(C, lx_sky_cie(C, 5, sun, LX_SKY_BY_ZENITH, 1000, &s));
    double E = SENT;
    EXPECT_EINVAL(lx_sky_illuminance(NULL, &s, up, 0, &E));
    assert_true(E == SENT);
}
static void t_lx_sun_spa(void)
{
    lx_sun_input in = {.year = 2003, .month = 10, .day = 17, .hour = 12, .minute = 30, .second = 30,
                       .timezone_h = -7, .delta_t_s = 67, .latitude_deg = 39.742476, .longitude_deg = -105.1786,
                       .elevation_m = 1830.14, .pressure_mbar = 820, .temperature_C = 11, .refraction_deg = 0.5667};
    lx_sun_position pos, ref;
    memset(&pos, 0xab, sizeof pos);
    ref = pos;
    EXPECT_EINVAL(lx_sun_spa(NULL, &in, &pos));
    assert_memory_equal(&pos, &ref, sizeof pos);
}
static void t_lx_sky_map(void)
{
    lx_sky s;
    const double sun[3] = {0, 0.5, 0.8};
    lx_assert_ok(C, lx_sky_cie(C, 5, sun, LX_SKY_BY_ZENITH, 1000, &s));
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_sky_map(NULL, &s, NULL, &m));
    assert_ptr_equal(m, PSENT);
}
static void t_lx_scene_glare_eval(void)
{
    lx_scene_glare *g = PSENT;
    EXPECT_EINVAL(lx_scene_glare_eval(NULL, SCENE, &g));
    assert_ptr_equal(g, PSENT);
}

static void t_lx_warn_cone_flux(void)
{
    double f = 42, r = 42;
    EXPECT_EINVAL(lx_warn_cone_flux(NULL, 800, 1, 0.5, &f, &r));
    assert_true(f == 42 && r == 42);
}
static void t_lx_envmap_concentration(void)
{
    double f = 42;
    size_t k = 42;
    EXPECT_EINVAL(lx_envmap_concentration(NULL, NULL, 1e-3, &f, &k));
    assert_true(f == 42 && k == 42);
}
static void t_lx_ctx_irradiance_method(void)
{
    double q = 0;
    assert_int_equal(lx_ctx_irradiance_method(NULL, &q), LX_IRR_AUTO);
    assert_true(isnan(q));
}
/* the readers of instrument exports, PAR, hazards and binning */
static void t_lx_spd_read_file_opts(void)
{
    lx_spd_set *s = PSENT;
    EXPECT_EINVAL(lx_spd_read_file_opts(NULL, SPD_FILE, NULL, &s));
    assert_ptr_equal(s, PSENT);
}
static void t_lx_spd_read_mem_opts(void)
{
    lx_spd_set *s = PSENT;
    EXPECT_EINVAL(lx_spd_read_mem_opts(NULL, "a.csv", SPD_TEXT, strlen(SPD_TEXT), NULL, &s));
    assert_ptr_equal(s, PSENT);
}
static void t_lx_spd_set_vendor(void)
{
    lx_spd_set *set = NULL;
    lx_assert_ok(C, lx_spd_read_mem(C, "a.csv", SPD_TEXT, strlen(SPD_TEXT), &set));
    lx_vendor_results v;
    v.cct_K = SENT;
    EXPECT_EINVAL(lx_spd_set_vendor(NULL, set, &v));
    assert_true(v.cct_K == SENT);
    lx_spd_set_free(set);
}
static void t_lx_binning_compute(void)
{
    lx_binning b;
    b.sdcm = SENT;
    EXPECT_EINVAL(lx_binning_compute(NULL, 0.38, 0.38, 4000, 0, &b));
    assert_true(b.sdcm == SENT);
}
static void t_lx_binning_batch(void)
{
    lx_binning b[2];
    b[0].sdcm = SENT;
    EXPECT_EINVAL(lx_binning_batch(NULL, &BATCH, NULL, b));
    assert_true(b[0].sdcm == SENT);
}
static void t_lx_par_compute(void)
{
    lx_par p;
    p.ppfd = SENT;
    EXPECT_EINVAL(lx_par_compute(NULL, &D65, LX_METHOD_AUTO, &p));
    assert_true(p.ppfd == SENT);
}
static void t_lx_par_batch(void)
{
    lx_par p[2];
    p[0].ppfd = SENT;
    EXPECT_EINVAL(lx_par_batch(NULL, &BATCH, NULL, p));
    assert_true(p[0].ppfd == SENT);
}
static void t_lx_hazard_compute(void)
{
    lx_hazard h;
    h.value[0] = SENT;
    EXPECT_EINVAL(lx_hazard_compute(NULL, &D65, LX_METHOD_AUTO, &h));
    assert_true(h.value[0] == SENT);
}
static void t_lx_hazard_batch(void)
{
    lx_hazard h[2];
    h[0].value[0] = SENT;
    EXPECT_EINVAL(lx_hazard_batch(NULL, &BATCH, NULL, h));
    assert_true(h[0].value[0] == SENT);
}
static void t_lx_hazard_risk_group(void)
{
    lx_hazard h = {{1, 1, 1, 1}, {1, 1, 1, 1}, {0}};
    lx_hazard_risk r;
    r.group = (lx_risk_group)7;
    EXPECT_EINVAL(lx_hazard_risk_group(NULL, &h, 1, 0.01, &r));
    assert_int_equal(r.group, 7);
}

static void t_lx_lab_batch(void)
{
    lx_par p[2];
    p[0].ppfd = SENT;
    EXPECT_EINVAL(lx_lab_batch(NULL, &BATCH, NULL, p, NULL, NULL));
    assert_true(p[0].ppfd == SENT);
}

#define CASE(f) {#f, t_##f}
static const struct api_case {
    const char *name;
    void (*run)(void);
} CASES[] = {
    CASE(lx_ctx_set_input_limit), CASE(lx_ctx_input_limit), CASE(lx_colorimetry_check), CASE(lx_ugr),
    CASE(lx_ugr_table_compute), CASE(lx_ugr_table_text), CASE(lx_dominant_wavelength), CASE(lx_spd_shape_compute), CASE(lx_sky_cie), CASE(lx_sky_cie_params), CASE(lx_sky_perez), CASE(lx_sky_illuminance),
    CASE(lx_sun_spa), CASE(lx_sky_map), CASE(lx_scene_glare_eval), CASE(lx_warn_cone_flux), CASE(lx_envmap_concentration),
    CASE(lx_ctx_irradiance_method),
    CASE(lx_spd_read_file_opts), CASE(lx_spd_read_mem_opts), CASE(lx_spd_set_vendor), CASE(lx_binning_compute),
    CASE(lx_binning_batch), CASE(lx_par_compute), CASE(lx_par_batch), CASE(lx_hazard_compute), CASE(lx_hazard_batch),
    CASE(lx_hazard_risk_group), CASE(lx_lab_batch),
    CASE(lx_ctx_create), CASE(lx_ctx_destroy), CASE(lx_ctx_errmsg), CASE(lx_ctx_errfile), CASE(lx_ctx_errline),
    CASE(lx_ctx_set_log), CASE(lx_ctx_backend_used), CASE(lx_cl_ready), CASE(lx_ctx_counters),
    CASE(lx_ctx_counters_reset), CASE(lx_backend_parse), CASE(lx_simd_parse), CASE(lx_cl_select), CASE(lx_cl_borrow),
    CASE(lx_cl_devices), CASE(lx_cl_info), CASE(lx_function_get), CASE(lx_illuminant_get), CASE(lx_tcs_get),
    CASE(lx_daylight), CASE(lx_daylight_xy), CASE(lx_spd_read_file), CASE(lx_spd_read_mem), CASE(lx_spd_read_stream),
    CASE(lx_file_open), CASE(lx_cct_from_uv_batch), CASE(lx_batch_table_stream_ex), CASE(lx_spd_check),
    CASE(lx_spd_integrate), CASE(lx_spd_integrate_radiant), CASE(lx_spd_colorimetry),
    CASE(lx_colorimetry_from_integrals), CASE(lx_cct_from_uv), CASE(lx_cct_from_xy), CASE(lx_planck_uv),
    CASE(lx_batch_integrate), CASE(lx_batch_table_read), CASE(lx_batch_table_read_mem), CASE(lx_batch_table_stream),
    CASE(lx_batch_table_integrate_file), CASE(lx_batch_resample), CASE(lx_batch_colorimetry),
    CASE(lx_alphaopic_compute), CASE(lx_alphaopic_batch), CASE(lx_mesopic_luminance),
    CASE(lx_efficacy_from_spd_file), CASE(lx_cri_compute), CASE(lx_tm30_compute), CASE(lx_unit_find),
    CASE(lx_quantity_parse), CASE(lx_unit_convert), CASE(lx_unit_format), CASE(lx_radiometric_convert),
    CASE(lx_point_illuminance), CASE(lx_point_intensity), CASE(lx_warn_intensity), CASE(lx_warn_exponent_from_beam),
    CASE(lx_warn_beam_from_exponent), CASE(lx_disk_illuminance), CASE(lx_rect_illuminance),
    CASE(lx_lambertian_luminance), CASE(lx_solve_distance), CASE(lx_solve_intensity), CASE(lx_solve_flux),
    CASE(lx_solid_angle_cap), CASE(lx_solid_angle_latlong_pixel), CASE(lx_solid_angle_rect),
    CASE(lx_luminaire_read_file), CASE(lx_luminaire_read_mem), CASE(lx_luminaire_summary),
    CASE(lx_luminaire_from_model), CASE(lx_luminaire_write_ies), CASE(lx_plane_axis), CASE(lx_grid_illuminance),
    CASE(lx_plane_points), CASE(lx_grid_stats_compute), CASE(lx_envmap_create_cube), CASE(lx_envmap_create),
    CASE(lx_envmap_luminance), CASE(lx_envmap_downsample), CASE(lx_rgb_y_weights), CASE(lx_exr_read),
    CASE(lx_exr_read_any), CASE(lx_envmap_write_exr), CASE(lx_sh9_project), CASE(lx_sh9_irradiance),
    CASE(lx_irradiance_dirs), CASE(lx_irradiance_map), CASE(lx_spectral_exr_read_xyz), CASE(lx_xyz_image_write_exr),
    CASE(lx_scene_read_file), CASE(lx_scene_read_mem), CASE(lx_scene_plan_make), CASE(lx_scene_eval),
    CASE(lx_scene_plan_make_mode), CASE(lx_en12464_grid_size), CASE(lx_scene_area_stats), CASE(lx_scene_check),
    CASE(lx_leni_compute), CASE(lx_scene_energy), CASE(lx_scene_report_write_pdf),
    CASE(lx_falsecolor_write_png), CASE(lx_envmap_preview_write_png), CASE(lx_irradiance_write_png),
    CASE(lx_spd_report_write_png), CASE(lx_tm30_report_write_png), CASE(lx_xyz_image_write_png), CASE(lx_grid_write_png), CASE(lx_error_time_write_png),
    CASE(lx_scene_outlines), CASE(lx_scene_receiver_plane), CASE(lx_scene_receiver_write_png),
    CASE(lx_plane_cells), CASE(lx_unc_model_create), CASE(lx_unc_model_add), CASE(lx_unc_model_parse),
    CASE(lx_spd_uncertainty),
};
#define NCASES (sizeof CASES / sizeof CASES[0])

static void null_context_everywhere(void **state)
{
    (void)state;
    for (size_t i = 0; i < NCASES; i++) {
        print_message("%s(NULL, ...)\n", CASES[i].name);
        CASES[i].run();
    }
}

/* Every LX_API function of the header whose first parameter is a context has a case above. */
static void every_context_function_has_a_case(void **state)
{
    (void)state;
    FILE *f = fopen("src/luxcalc.h", "rb");
    if (!f) {
        print_message("src/luxcalc.h not found from the working directory: skipped\n");
        skip();
    }
    static char text[1 << 20];
    size_t len = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[len] = 0;
    int missing = 0, seen = 0;
    for (const char *p = strstr(text, "\nLX_API "); p; p = strstr(p + 1, "\nLX_API ")) {
        const char *paren = strchr(p, '('), *semi = strchr(p, ';');
        if (!paren || !semi || semi < paren) continue;
        const char *e = paren;
        while (e > p && e[-1] == ' ') e--;
        const char *b = e;
        while (b > p && (b[-1] == '_' || (b[-1] >= 'a' && b[-1] <= 'z') || (b[-1] >= '0' && b[-1] <= '9'))) b--;
        char name[96];
        snprintf(name, sizeof name, "%.*s", (int)(e - b), b);
        const char *comma = strpbrk(paren, ",)");
        char first[128];
        snprintf(first, sizeof first, "%.*s", (int)(comma - paren - 1), paren + 1);
        if (!strstr(first, "lx_ctx")) continue;
        seen++;
        size_t i = 0;
        while (i < NCASES && strcmp(CASES[i].name, name)) i++;
        if (i == NCASES) {
            print_error("%s takes a context but has no NULL-context case in tests/test_api.c\n", name);
            missing++;
        }
    }
    print_message("%d context-taking functions in the header, %zu cases\n", seen, NCASES);
    assert_true(seen >= 90);
    assert_int_equal(missing, 0);
}

/* LX_VERSION_* of the header equal what the library reports, and the string is MAJOR.MINOR.PATCH. */
static void version_macros_match_the_library(void **state)
{
    (void)state;
    char want[64];
    snprintf(want, sizeof want, "%d.%d.%d", LX_VERSION_MAJOR, LX_VERSION_MINOR, LX_VERSION_PATCH);
    assert_string_equal(LX_VERSION_STRING, want);
    assert_string_equal(lx_version(), want);
    int a = -1, b = -1, c = -1, n = -1;
    assert_int_equal(sscanf(lx_version(), "%d.%d.%d%n", &a, &b, &c, &n), 3);
    assert_int_equal((size_t)n, strlen(lx_version()));
    assert_int_equal(a, LX_VERSION_MAJOR);
    assert_int_equal(b, LX_VERSION_MINOR);
    assert_int_equal(c, LX_VERSION_PATCH);
}

/* ABI policy: an option struct with non-zero reserved space is refused by every function that reads one. */
static void nonzero_reserved_options_refused(void **state)
{
    lx_ctx *ctx = *state;
    double out[4];
    lx_batch_opts bo = {.backend = LX_BACKEND_CPU};
    bo.reserved[3] = 1;
    EXPECT_EINVAL(lx_batch_integrate(ctx, &BATCH, FNS, 2, &bo, out));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "reserved"));
    lx_colorimetry cc[2];
    EXPECT_EINVAL(lx_batch_colorimetry(ctx, &BATCH, LX_OBSERVER_2, &bo, cc));
    EXPECT_EINVAL(lx_alphaopic_batch(ctx, &BATCH, &bo, out));
    lx_leni_input li = {.area_m2 = 10, .power_W = 100, .night_h = 100, .constant_factor = 1, .occupancy_factor = 1,
                        .daylight_factor = 1};
    li.reserved[0] = 1;
    lx_leni le;
    EXPECT_EINVAL(lx_leni_compute(ctx, &li, &le));
    lx_pdf_report_opts pro = {0};
    pro.reserved[2] = 1;
    EXPECT_EINVAL(lx_scene_report_write_pdf(ctx, SCENE, &pro, "/nonexistent/r.pdf"));
    lx_par pb[2];
    lx_hazard hb[2];
    lx_binning bb[2];
    EXPECT_EINVAL(lx_par_batch(ctx, &BATCH, &bo, pb));
    EXPECT_EINVAL(lx_hazard_batch(ctx, &BATCH, &bo, hb));
    EXPECT_EINVAL(lx_binning_batch(ctx, &BATCH, &bo, bb));
    lx_spd_read_opts rdo = {.skip_bad_rows = 1};
    rdo.reserved[2] = 1;
    lx_spd_set *set = PSENT;
    EXPECT_EINVAL(lx_spd_read_mem_opts(ctx, "a.csv", SPD_TEXT, strlen(SPD_TEXT), &rdo, &set));
    assert_null(set);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "reserved"));
    const double lam[3] = {500, 510, 520}, val[3] = {1, 2, 3};
    const size_t off[1] = {0}, nin[1] = {3};
    double dv[3];
    lx_batch dst = {.n_lambda = 3, .start_nm = 500, .step_nm = 10, .dtype = LX_F64, .values = dv};
    EXPECT_EINVAL(lx_batch_resample(ctx, 1, lam, val, off, nin, &dst, &bo));

    lx_grid_opts go = {.model = LX_MODEL_POINT};
    go.reserved[0] = 1;
    lx_placement pl = {.pos_m = {0, 0, 2}, .aim = {0, 0, -1}};
    pl.lum = LUM;
    const double pts[3] = {0, 0, 0}, up[3] = {0, 0, 1};
    EXPECT_EINVAL(lx_grid_illuminance(ctx, &pl, 1, pts, 1, up, 1, &go, out));

    lx_irr_opts io = {.method = LX_IRR_SH9};
    io.reserved[1] = -1;
    EXPECT_EINVAL(lx_irradiance_dirs(ctx, MAP, 1, up, &io, out));
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_irradiance_map(ctx, MAP, 0, 0, &io, &m));
    assert_null(m);

    lx_unc_model *um = NULL;
    assert_int_equal(lx_unc_model_parse(ctx, "1%", NULL, &um), LX_OK);
    lx_unc_opts uo = {.trials = 100};
    uo.reserved[0] = 1;
    lx_unc_result *ur = PSENT;
    EXPECT_EINVAL(lx_spd_uncertainty(ctx, &D65, um, &uo, &ur));
    assert_null(ur);
    lx_unc_component uc = {.kind = LX_UNC_SCALE, .sigma = 0.01};
    uc.reserved[3] = 1;
    EXPECT_EINVAL(lx_unc_model_add(ctx, um, &uc));
    lx_unc_model_free(um);

    lx_exr_write_opts eo = {0};
    eo.reserved[2] = 7;
    const char *p = out_path("reserved.exr");
    EXPECT_EINVAL(lx_envmap_write_exr(ctx, p, MAP, &eo));
    assert_absent(p);

    lx_scene_eval_opts so = {0};
    so.reserved[0] = 1;
    lx_scene_result *r = PSENT;
    EXPECT_EINVAL(lx_scene_eval(ctx, SCENE, PLAN, &so, &r));
    assert_null(r);

    lx_lum_model lm = {.kind = LX_LUM_MODEL_POINT, .flux_lm = 1000};
    lm.reserved[0] = 1;
    lx_luminaire *l = PSENT;
    EXPECT_EINVAL(lx_luminaire_from_model(ctx, &lm, &l));
    assert_null(l);

    /* the plots' options: nothing appears at the path */
    const double E[4] = {1, 2, 3, 4};
    lx_falsecolor_opts fo = {0};
    fo.reserved[3] = 1;
    p = out_path("reserved_f.png");
    EXPECT_EINVAL(lx_falsecolor_write_png(ctx, p, 2, 2, E, &fo));
    assert_absent(p);
    lx_isolux_opts iso = {0};
    iso.reserved[0] = 2;
    p = out_path("reserved_g.png");
    EXPECT_EINVAL(lx_grid_write_png(ctx, p, &PLANE, E, &iso));
    assert_absent(p);
    lx_receiver_png_opts rpo = {0};
    rpo.reserved[2] = 1;
    p = out_path("reserved_s.png");
    EXPECT_EINVAL(lx_scene_receiver_write_png(ctx, p, SCENE, NULL, 0, &rpo));
    assert_absent(p);
#if defined(__LP64__)
    /* the outlines and the quantity took lx_isolux_opts' reserved space: its size and the offset of
     * every earlier field are those of 0.2.0 (the same struct with long long reserved[4]) */
    struct isolux_020 {
        lx_isolux_background background;
        lx_plot_scale scale;
        const lx_plot_mark *marks;
        size_t n_marks;
        const char *source, *surface, *caption;
        double area_m[4];
        int imperial;
        long long reserved[4];
    };
    assert_int_equal(sizeof(lx_isolux_opts), sizeof(struct isolux_020));
    assert_int_equal(offsetof(lx_isolux_opts, imperial), offsetof(struct isolux_020, imperial));
    assert_int_equal(offsetof(lx_isolux_opts, outlines), offsetof(struct isolux_020, reserved));
#endif
    lx_report_opts ro = {0};
    ro.reserved[1] = 1;
    p = out_path("reserved_r.png");
    EXPECT_EINVAL(lx_spd_report_write_png(ctx, &D65, &ro, p));
    assert_absent(p);

    /* daylight: the sky map's options and the Perez and SPA inputs */
    const double sun[3] = {0, 0.5, 0.8};
    lx_sky sky;
    lx_assert_ok(ctx, lx_sky_cie(ctx, 12, sun, LX_SKY_BY_ZENITH, 5000, &sky));
    lx_sky_map_opts mo = {.width = 16, .height = 8};
    mo.reserved[3] = 1;
    m = PSENT;
    EXPECT_EINVAL(lx_sky_map(ctx, &sky, &mo, &m));
    assert_null(m);
    lx_perez_input pi = {.sun_dir = {0, 0.5, 0.8}, .direct_normal_W_m2 = 500, .diffuse_horizontal_W_m2 = 100,
                         .day_of_year = 172};
    pi.reserved[0] = 1;
    lx_sky ps;
    EXPECT_EINVAL(lx_sky_perez(ctx, &pi, &ps));
    lx_sun_input si = {.year = 2003, .month = 10, .day = 17, .hour = 12, .timezone_h = -7, .delta_t_s = 67,
                       .latitude_deg = 39.7, .longitude_deg = -105.2, .pressure_mbar = 820, .temperature_C = 11,
                       .refraction_deg = 0.5667};
    si.reserved[1] = 1;
    lx_sun_position sp;
    EXPECT_EINVAL(lx_sun_spa(ctx, &si, &sp));
}

/* ABI policy: results are written whole, their reserved space as zero (whatever the caller left there). */
static void results_write_reserved_as_zero(void **state)
{
    lx_ctx *ctx = *state;
    static const long long zero[4];
#define DIRTY(x) memset(&(x), 0xcd, sizeof(x))
/* the reserved space a result has left (a later result takes some of it: lx_counters kept 1 of 4) */
#define ZERO_RESERVED(x) assert_memory_equal((x).reserved, zero, sizeof (x).reserved)
    lx_colorimetry c;
    DIRTY(c);
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &D65, LX_OBSERVER_2, LX_METHOD_AUTO, &c));
    ZERO_RESERVED(c);
    lx_colorimetry cb[2];
    DIRTY(cb);
    lx_assert_ok(ctx, lx_batch_colorimetry(ctx, &BATCH, LX_OBSERVER_2, NULL, cb));
    ZERO_RESERVED(cb[0]);
    ZERO_RESERVED(cb[1]);
    lx_cri cri;
    DIRTY(cri);
    lx_assert_ok(ctx, lx_cri_compute(ctx, &D65, &cri));
    ZERO_RESERVED(cri);
    lx_dominant dom;
    DIRTY(dom);
    lx_assert_ok(ctx, lx_dominant_wavelength(ctx, LX_OBSERVER_2, 0.5, 0.4, 1.0 / 3, 1.0 / 3, &dom));
    ZERO_RESERVED(dom);
    lx_spd_shape shp;
    DIRTY(shp);
    lx_assert_ok(ctx, lx_spd_shape_compute(ctx, &D65, &shp));
    ZERO_RESERVED(shp);
    lx_unc_model *um = NULL;
    lx_assert_ok(ctx, lx_unc_model_parse(ctx, "1%", NULL, &um));
    lx_unc_opts uo = {.method = LX_UNC_GUM};
    lx_unc_result *ur = NULL;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &D65, um, &uo, &ur));
    for (size_t i = 0; i < ur->nq; i++) ZERO_RESERVED(ur->q[i]);
    lx_unc_result_free(ur);
    lx_unc_model_free(um);
    static lx_tm30 tm;
    DIRTY(tm);
    lx_assert_ok(ctx, lx_tm30_compute(ctx, &D65, &tm));
    ZERO_RESERVED(tm);
    lx_alphaopic ao;
    DIRTY(ao);
    lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &D65, LX_METHOD_AUTO, &ao));
    ZERO_RESERVED(ao);
    lx_par par, parb[2];
    DIRTY(par);
    DIRTY(parb);
    lx_assert_ok(ctx, lx_par_compute(ctx, &D65, LX_METHOD_AUTO, &par));
    lx_assert_ok(ctx, lx_par_batch(ctx, &BATCH, NULL, parb));
    ZERO_RESERVED(par);
    ZERO_RESERVED(parb[1]);
    lx_hazard hz, hzb[2];
    DIRTY(hz);
    DIRTY(hzb);
    lx_assert_ok(ctx, lx_hazard_compute(ctx, &D65, LX_METHOD_AUTO, &hz));
    lx_assert_ok(ctx, lx_hazard_batch(ctx, &BATCH, NULL, hzb));
    ZERO_RESERVED(hz);
    ZERO_RESERVED(hzb[1]);
    lx_hazard_risk risk;
    DIRTY(risk);
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &hz, 0, 0, &risk));
    ZERO_RESERVED(risk);
    lx_binning bin, binb[2];
    DIRTY(bin);
    DIRTY(binb);
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.38, 0.38, 4000, 0.001, &bin));
    lx_assert_ok(ctx, lx_binning_batch(ctx, &BATCH, NULL, binb));
    ZERO_RESERVED(bin);
    ZERO_RESERVED(binb[1]);
    lx_spd_set *vs = NULL;
    static const char up[] = "Model Name\tCV600\nCCT\t5000\n380nm\t1\n381nm\t2\n";
    lx_spd_read_opts ro = {.skip_bad_rows = 1};
    lx_assert_ok(ctx, lx_spd_read_mem_opts(ctx, "u.txt", up, sizeof up - 1, &ro, &vs));
    lx_vendor_results vr;
    DIRTY(vr);
    lx_assert_ok(ctx, lx_spd_set_vendor(ctx, vs, &vr));
    ZERO_RESERVED(vr);
    for (size_t i = 0; i < vs->nfields; i++) assert_memory_equal(vs->fields[i].reserved, zero, sizeof vs->fields[i].reserved);
    lx_spd_set_free(vs);
    static const char bad[] = "nm,A\n380,1\n385,x\n390,2\n";
    lx_assert_ok(ctx, lx_spd_read_mem_opts(ctx, "b.csv", bad, sizeof bad - 1, &ro, &vs));
    assert_int_equal(vs->nskipped, 1);
    assert_memory_equal(vs->skipped[0].reserved, zero, sizeof vs->skipped[0].reserved);
    lx_spd_set_free(vs);
    lx_source_result sr;
    DIRTY(sr);
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, 1, 0, LX_MODEL_AUTO, &sr));
    ZERO_RESERVED(sr);
    DIRTY(sr);
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1, 2, 2, 0, 0, LX_MODEL_AUTO, &sr));
    ZERO_RESERVED(sr);
    lx_lum_summary ls;
    DIRTY(ls);
    lx_assert_ok(ctx, lx_luminaire_summary(ctx, LUM, &ls));
    ZERO_RESERVED(ls);
    lx_grid_stats gs;
    DIRTY(gs);
    const double E[2] = {1, 3};
    lx_assert_ok(ctx, lx_grid_stats_compute(ctx, E, 2, &gs));
    ZERO_RESERVED(gs);
    lx_counters k;
    DIRTY(k);
    lx_ctx_counters(ctx, &k);
    ZERO_RESERVED(k);
    for (size_t i = 0; i < SCENE->n_lum; i++) ZERO_RESERVED(SCENE->lum[i]);
    for (size_t i = 0; i < SCENE->n_rec; i++) ZERO_RESERVED(SCENE->rec[i]);
    lx_cl_device_info *d = NULL;
    size_t n = 0;
    lx_assert_ok(ctx, lx_cl_devices(ctx, &d, &n));
    for (size_t i = 0; i < n; i++) ZERO_RESERVED(d[i]);
    lx_cl_devices_free(d);
    /* daylight and glare */
    const double sun[3] = {0, 0.5, 0.8};
    lx_sky sky;
    DIRTY(sky);
    lx_assert_ok(ctx, lx_sky_cie(ctx, 12, sun, LX_SKY_BY_ZENITH, 5000, &sky));
    ZERO_RESERVED(sky);
    lx_perez_input pi = {.sun_dir = {0, 0.5, 0.8}, .direct_normal_W_m2 = 500, .diffuse_horizontal_W_m2 = 100,
                         .day_of_year = 172};
    DIRTY(sky);
    lx_assert_ok(ctx, lx_sky_perez(ctx, &pi, &sky));
    ZERO_RESERVED(sky);
    lx_sun_input si = {.year = 2003, .month = 10, .day = 17, .hour = 12, .timezone_h = -7, .delta_t_s = 67,
                       .latitude_deg = 39.7, .longitude_deg = -105.2, .pressure_mbar = 820, .temperature_C = 11,
                       .refraction_deg = 0.5667};
    lx_sun_position sp;
    DIRTY(sp);
    lx_assert_ok(ctx, lx_sun_spa(ctx, &si, &sp));
    ZERO_RESERVED(sp);
    /* openings: the opening, the plan's and the result's daylight parts */
    static const char *day_text = "[scene]\npatch_size = 1 m\n[room r]\nsize = 4, 4, 3 m\n"
                                  "[opening w]\ncorner = 1, 0, 1 m\nedge1 = 2, 0, 0 m\nedge2 = 0, 0, 1 m\n"
                                  "[sky]\ntype = overcast\nluminance = 1000 cd/m2\n"
                                  "[receiver p]\ntype = point\nposition = 2, 2, 0.8 m\n";
    lx_scene *dsc = NULL;
    lx_scene_plan *dp = NULL;
    lx_scene_result *dr = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "day.scene", day_text, strlen(day_text), &dsc));
    lx_assert_ok(ctx, lx_scene_plan_make(ctx, dsc, LX_BACKEND_CPU, &dp));
    lx_assert_ok(ctx, lx_scene_eval(ctx, dsc, dp, NULL, &dr));
    ZERO_RESERVED(dsc->open[0]);
    ZERO_RESERVED(dp->daylight);
    ZERO_RESERVED(dp->room);
    ZERO_RESERVED(dr->daylight);
    ZERO_RESERVED(dr->room);
    lx_scene_result_free(dr);
    lx_scene_plan_free(dp);
    lx_scene_free(dsc);
    lx_lum_model pm = {.kind = LX_LUM_MODEL_LAMBERT, .flux_lm = 1000, .width_m = 0.6, .length_m = 0.6};
    lx_luminaire *panel = NULL;
    lx_assert_ok(ctx, lx_luminaire_from_model(ctx, &pm, &panel));
    lx_ugr_table *ut = malloc(sizeof *ut);
    DIRTY(*ut);
    lx_assert_ok(ctx, lx_ugr_table_compute(ctx, panel, ut));
    ZERO_RESERVED(*ut);
    free(ut);
    lx_luminaire_free(panel);
    lx_en12464_grid g;
    DIRTY(g);
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 5, 4, LX_GRID_ROUND_NEAREST, &g));
    ZERO_RESERVED(g);
    lx_scene_result *ar = NULL;
    lx_assert_ok(ctx, lx_scene_eval(ctx, SCENE, PLAN, NULL, &ar));
    lx_area_stats as;
    DIRTY(as);
    lx_assert_ok(ctx, lx_scene_area_stats(ctx, SCENE, ar, 0, &as));
    ZERO_RESERVED(as);
    lx_leni_input li = {.area_m2 = 10, .power_W = 100, .night_h = 100, .constant_factor = 1, .occupancy_factor = 1,
                        .daylight_factor = 1};
    lx_leni le;
    DIRTY(le);
    lx_assert_ok(ctx, lx_leni_compute(ctx, &li, &le));
    ZERO_RESERVED(le);
    lx_scene_result_free(ar);
}

/* Creating functions set *out to NULL when they fail (here: on an argument they refuse). */
static void failed_creators_leave_null(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *s = PSENT;
    assert_int_equal(lx_spd_read_file(ctx, "/nonexistent/x.csv", &s), LX_EIO);
    assert_null(s);
    s = PSENT;
    assert_int_equal(lx_spd_read_mem(ctx, "bad.csv", "x\n", 2, &s), LX_EPARSE);
    assert_null(s);
    lx_batch_table *t = PSENT;
    assert_int_equal(lx_batch_table_read(ctx, "/nonexistent/x.csv", LX_F64, 1, &t), LX_EIO);
    assert_null(t);
    t = PSENT;
    EXPECT_EINVAL(lx_batch_table_read_mem(ctx, "m.csv", "id,500\na,1\n", 11, (lx_dtype)9, 1, &t));
    assert_null(t);
    double *r = PSENT;
    size_t nr = 0;
    assert_int_equal(lx_batch_table_integrate_file(ctx, "/nonexistent/x.csv", FNS, 2, 1, &r, &nr), LX_EIO);
    assert_null(r);
    lx_luminaire *l = PSENT;
    assert_int_equal(lx_luminaire_read_file(ctx, "/nonexistent/x.ies", &l), LX_EIO);
    assert_null(l);
    l = PSENT;
    lx_lum_model bad = {.kind = (lx_lum_model_kind)9, .flux_lm = 1000};
    EXPECT_EINVAL(lx_luminaire_from_model(ctx, &bad, &l));
    assert_null(l);
    char *text = PSENT;
    size_t len = 0;
    lx_luminaire nocd;
    memset(&nocd, 0, sizeof nocd);
    EXPECT_EINVAL(lx_luminaire_write_ies(ctx, &nocd, &text, &len));
    assert_null(text);
    double *pts = PSENT;
    size_t np = 0;
    lx_plane empty = PLANE;
    empty.na = 0;
    EXPECT_EINVAL(lx_plane_points(ctx, &empty, &pts, &np));
    assert_null(pts);
    lx_envmap *m = PSENT;
    EXPECT_EINVAL(lx_envmap_create(ctx, 0, 4, 1, &m));
    assert_null(m);
    m = PSENT;
    EXPECT_EINVAL(lx_envmap_create_cube(ctx, 0, 1, &m));
    assert_null(m);
    m = PSENT;
    EXPECT_EINVAL(lx_envmap_downsample(ctx, MAP, 3, 4, &m));
    assert_null(m);
    m = PSENT;
    assert_int_equal(lx_exr_read(ctx, "/nonexistent/x.exr", &m), LX_EIO);
    assert_null(m);
    m = PSENT;
    EXPECT_EINVAL(lx_irradiance_map(ctx, MAP, 3, 0, NULL, &m));
    assert_null(m);
    lx_xyz_image *img = PSENT;
    assert_int_equal(lx_spectral_exr_read_xyz(ctx, "/nonexistent/x.exr", LX_OBSERVER_2, NULL, &img), LX_EIO);
    assert_null(img);
    lx_scene *sc = PSENT;
    assert_int_equal(lx_scene_read_file(ctx, "/nonexistent/x.scene", &sc), LX_EIO);
    assert_null(sc);
    lx_scene_plan *p = PSENT;
    EXPECT_EINVAL(lx_scene_plan_make(ctx, SCENE, (lx_backend)9, &p));
    assert_null(p);
    lx_scene_result *res = PSENT;
    lx_scene_eval_opts one = {.single = 1, .index = 99};
    EXPECT_EINVAL(lx_scene_eval(ctx, SCENE, PLAN, &one, &res));
    assert_null(res);
}

/* The free functions accept NULL (and the objects' free functions too). */
static void free_functions_accept_null(void **state)
{
    (void)state;
    lx_text_free(NULL);
    lx_cl_devices_free(NULL);
    lx_batch_results_free(NULL);
    lx_plane_points_free(NULL);
    lx_spd_set_free(NULL);
    lx_batch_table_free(NULL);
    lx_luminaire_free(NULL);
    lx_envmap_free(NULL);
    lx_xyz_image_free(NULL);
    lx_scene_free(NULL);
    lx_scene_plan_free(NULL);
    lx_scene_result_free(NULL);
    lx_scene_checks_free(NULL);
    lx_scene_outlines_free(NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(null_context_everywhere),
        cmocka_unit_test(every_context_function_has_a_case),
        cmocka_unit_test(version_macros_match_the_library),
        cmocka_unit_test_setup_teardown(nonzero_reserved_options_refused, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(results_write_reserved_as_zero, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(failed_creators_leave_null, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test(free_functions_accept_null),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
