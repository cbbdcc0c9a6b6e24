/* test_fuzz.c - replays the fuzz targets' regression inputs (tests/fuzz/regressions/TARGET/,
 * every input that once crashed or misbehaved) and their seed corpora through the same harness
 * functions the fuzzers run, so a fixed finding stays fixed. */
#include "lx_test.h"

#include <dirent.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz/fuzz_batch.c"
#include "fuzz/fuzz_exr.c"
#include "fuzz/fuzz_ies.c"
#include "fuzz/fuzz_instruments.c"
#include "fuzz/fuzz_scene.c"
#include "fuzz/fuzz_spd.c"
#include "fuzz/fuzz_units.c"

typedef int (*harness)(const uint8_t *, size_t);

static int replay_dir(const char *dir, harness h)
{
    DIR *d = opendir(dir);
    if (!d) return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        char path[1024];
        struct stat sb;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (stat(path, &sb) != 0 || !S_ISREG(sb.st_mode) || sb.st_size > (1 << 24)) continue;
        FILE *f = fopen(path, "rb");
        if (!f) continue;
        uint8_t *buf = malloc((size_t)sb.st_size + 1);
        size_t got = buf ? fread(buf, 1, (size_t)sb.st_size, f) : 0;
        fclose(f);
        h(buf, got); /* aborts on a broken property, which fails the test binary */
        free(buf);
        n++;
    }
    closedir(d);
    return n;
}

static void test_spd_inputs(void **state)
{
    (void)state;
    int n = replay_dir("tests/fuzz/regressions/spd", fuzz_spd_one);
    n += replay_dir("tests/data/spd/good", fuzz_spd_one) + replay_dir("tests/data/spd/bad", fuzz_spd_one);
    n += replay_dir("samples/spd", fuzz_spd_one) + replay_dir("tests/bad/spd", fuzz_spd_one);
    assert_true(n >= 40); /* the readers' corpora are there */
}

static void test_ies_inputs(void **state)
{
    (void)state;
    int n = replay_dir("tests/fuzz/regressions/ies", fuzz_ies_one) + replay_dir("samples/ies", fuzz_ies_one);
    n += replay_dir("tests/data/ies/bad", fuzz_ies_one) + replay_dir("tests/bad/ies", fuzz_ies_one);
    n += replay_dir("tests/bad/ldt", fuzz_ies_one) + replay_dir("tests/bad/good", fuzz_ies_one);
    assert_true(n >= 60);
}

static void test_scene_inputs(void **state)
{
    (void)state;
    int n = replay_dir("tests/fuzz/regressions/scene", fuzz_scene_one) + replay_dir("samples/scenes", fuzz_scene_one);
    n += replay_dir("tests/data/scenes", fuzz_scene_one) + replay_dir("tests/bad/scene", fuzz_scene_one);
    n += replay_dir("tests/fuzz/seeds/scene", fuzz_scene_one); /* rooms, surfaces, obstructions */
    assert_true(n >= 19);
}

static void test_batch_inputs(void **state)
{
    (void)state;
    int n = replay_dir("tests/fuzz/regressions/batch", fuzz_batch_one) + replay_dir("tests/data/spd/good", fuzz_batch_one);
    n += replay_dir("tests/data/spd/bad", fuzz_batch_one) + replay_dir("tests/bad/spd", fuzz_batch_one);
    n += replay_dir("tests/fuzz/seeds/batch", fuzz_batch_one); /* rows the vector parser reads */
    assert_true(n >= 45);
}

static void test_exr_inputs(void **state)
{
    (void)state;
    int n = replay_dir("tests/fuzz/regressions/exr", fuzz_exr_one) + replay_dir("samples/envmaps", fuzz_exr_one);
    n += replay_dir("tests/bad/exr", fuzz_exr_one) + replay_dir("tests/fuzz/seeds/exr", fuzz_exr_one);
    assert_true(n >= 40);
}

static void test_instruments_inputs(void **state)
{
    (void)state;
    /* each file with a run of option bytes (layouts forced, bad rows skipped, units, columns) */
    int n = replay_dir("tests/fuzz/regressions/instruments", fuzz_instruments_one);
    n += replay_dir("tests/fuzz/seeds/instruments", fuzz_instruments_file);
    n += replay_dir("tests/data/instruments/good", fuzz_instruments_file) + replay_dir("tests/data/instruments/bad", fuzz_instruments_file);
    const char *shared = getenv("LX_SHARED_DIR");
    if (shared && *shared) {
        char dir[1024];
        snprintf(dir, sizeof dir, "%s/spectra/instruments", shared);
        replay_dir(dir, fuzz_instruments_file);
    }
    assert_true(n >= 40);
}

static void test_units_inputs(void **state)
{
    (void)state;
    int n = replay_dir("tests/fuzz/regressions/units", fuzz_units_one) + replay_dir("tests/fuzz/seeds/units", fuzz_units_one);
    assert_true(n >= 10);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spd_inputs),
        cmocka_unit_test(test_units_inputs),
        cmocka_unit_test(test_instruments_inputs),
        cmocka_unit_test(test_ies_inputs),
        cmocka_unit_test(test_scene_inputs),
        cmocka_unit_test(test_batch_inputs),
        cmocka_unit_test(test_exr_inputs),
    };
    return cmocka_run_group_tests_name("fuzz regressions", tests, NULL, NULL);
}
