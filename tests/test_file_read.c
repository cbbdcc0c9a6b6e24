/* test_file_read.c - the one whole-file reader (src/core/file_open.c, lx__read_all): the size
 * limit per kind (regular files refused unread, streams and devices at the limit, the
 * environment variable and the context setting), binary input refused from the first block
 * (NUL bytes, UTF-16, control bytes) with its line, and text that must pass (Latin-1, a DOS ^Z). */
#include "lx_test.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "core/core_private.h"

static char dir[64];

static void write_file(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Reads path as kind and expects status st whose message contains frag (NULL: success). */
static void expect(lx_ctx *ctx, const char *path, lx_input_kind kind, lx_status st, const char *frag, long line)
{
    char *text = NULL;
    size_t len = 0;
    lx_status got = lx__read_all(ctx, path, kind, &text, &len);
    if (got != st) print_error("%s: status %d (%s), expected %d\n", path, (int)got, lx_ctx_errmsg(ctx), (int)st);
    assert_int_equal(got, st);
    if (st == LX_OK) {
        assert_non_null(text);
        free(text);
        return;
    }
    assert_null(text);
    assert_int_equal(len, 0);
    if (!strstr(lx_ctx_errmsg(ctx), frag)) print_error("message '%s' lacks '%s'\n", lx_ctx_errmsg(ctx), frag);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), frag));
    assert_string_equal(lx_ctx_errfile(ctx), path);
    assert_int_equal(lx_ctx_errline(ctx), line);
}

/* The documented defaults (README "Robustness", limits.h) and how they change. */
static void limits_and_settings(void **state)
{
    lx_ctx *ctx = *state;
    unsetenv("LX_MAX_INPUT_MB");
    assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_SPECTRUM), (size_t)256 << 20);
    assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_LUMINAIRE), (size_t)16 << 20);
    assert_int_equal(lx_ctx_input_limit(NULL, LX_INPUT_SCENE), (size_t)16 << 20);
    setenv("LX_MAX_INPUT_MB", "3", 1);
    assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_SPECTRUM), (size_t)3 << 20);
    assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_SCENE), (size_t)3 << 20);
    const char *bad[] = {"0", "-1", "2.5", "1e3", "x", "1048577", "99999999999999999999999"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) { /* ignored: the defaults stand */
        setenv("LX_MAX_INPUT_MB", bad[i], 1);
        assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_SPECTRUM), (size_t)256 << 20);
    }
    setenv("LX_MAX_INPUT_MB", "1048576", 1);
    assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_LUMINAIRE), (size_t)1048576 << 20);
    unsetenv("LX_MAX_INPUT_MB");
    lx_assert_ok(ctx, lx_ctx_set_input_limit(ctx, LX_INPUT_SCENE, 1000));
    assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_SCENE), 1000);
    assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_SPECTRUM), (size_t)256 << 20); /* per kind */
    lx_assert_ok(ctx, lx_ctx_set_input_limit(ctx, LX_INPUT_SCENE, 0));
    assert_int_equal(lx_ctx_input_limit(ctx, LX_INPUT_SCENE), (size_t)16 << 20);
    assert_int_equal(lx_ctx_set_input_limit(ctx, (lx_input_kind)99, 5), LX_EINVAL);
    assert_int_equal(lx_ctx_input_limit(ctx, (lx_input_kind)99), 0);
}

/* A regular file: up to the limit it is read, one byte more is refused before it is read. */
static void regular_file_limit(void **state)
{
    lx_ctx *ctx = *state;
    char path[128], buf[4096];
    memset(buf, 'a', sizeof buf);
    for (int i = 99; i < 4096; i += 100) buf[i] = '\n';
    snprintf(path, sizeof path, "%s/limit.txt", dir);
    write_file(path, buf, 3000);
    lx_assert_ok(ctx, lx_ctx_set_input_limit(ctx, LX_INPUT_SPECTRUM, 3000));
    char *text = NULL;
    size_t len = 0;
    lx_assert_ok(ctx, lx__read_all(ctx, path, LX_INPUT_SPECTRUM, &text, &len));
    assert_int_equal(len, 3000);
    assert_memory_equal(text, buf, 3000);
    free(text);
    lx_assert_ok(ctx, lx_ctx_set_input_limit(ctx, LX_INPUT_SPECTRUM, 2999));
    expect(ctx, path, LX_INPUT_SPECTRUM, LX_EIO, "larger than 2999 bytes, the limit for a spectrum file (raise with LX_MAX_INPUT_MB)", 0);
    /* whole MB limits are said in MB */
    setenv("LX_MAX_INPUT_MB", "1", 1);
    lx_assert_ok(ctx, lx_ctx_set_input_limit(ctx, LX_INPUT_SPECTRUM, 0));
    char *big = malloc((1 << 20) + 1);
    assert_non_null(big);
    memset(big, '#', (1 << 20) + 1);
    snprintf(path, sizeof path, "%s/mb.txt", dir);
    write_file(path, big, (1 << 20) + 1);
    free(big);
    expect(ctx, path, LX_INPUT_SPECTRUM, LX_EIO, "larger than 1 MB, the limit for a spectrum file", 0);
    expect(ctx, path, LX_INPUT_SCENE, LX_EIO, "larger than 1 MB, the limit for a scene file", 0);
    unsetenv("LX_MAX_INPUT_MB");
    expect(ctx, path, LX_INPUT_SCENE, LX_OK, NULL, 0);
    expect(ctx, path, (lx_input_kind)7, LX_EINVAL, "unknown input kind", 0);
}

/* Binary data is refused from the first block, naming its line; text with high bytes passes. */
static void binary_input(void **state)
{
    lx_ctx *ctx = *state;
    char path[128];
    unsigned char b[8192];
    snprintf(path, sizeof path, "%s/bin", dir);
    /* a NUL on line 3 */
    memcpy(b, "nm,v\n500,1\n5\0" "00,2\n", 17);
    write_file(path, b, 17);
    expect(ctx, path, LX_INPUT_SPECTRUM, LX_EPARSE, "binary data (NUL byte at offset 12); not a text file", 3);
    /* a NUL far past the first block: still refused, with its line */
    static char late[200000];
    memset(late, 'x', sizeof late);
    for (size_t i = 79; i < sizeof late; i += 80) late[i] = '\n';
    late[150000] = 0;
    write_file(path, late, sizeof late);
    expect(ctx, path, LX_INPUT_LUMINAIRE, LX_EPARSE, "NUL byte at offset 150000", 150000 / 80 + 1);
    /* UTF-16 with a byte-order mark, either order, and without one */
    const char le[] = "\xFF\xFEn\0m\0,\0v\0\n\0";
    write_file(path, le, sizeof le - 1);
    expect(ctx, path, LX_INPUT_SPECTRUM, LX_EPARSE, "UTF-16 text is not supported; save the file as UTF-8", 1);
    const char be[] = "\xFE\xFF\0n\0m";
    write_file(path, be, sizeof be - 1);
    expect(ctx, path, LX_INPUT_SCENE, LX_EPARSE, "UTF-16 text is not supported", 1);
    const char nobom[] = "n\0m\0,\0v\0\n\0" "5\0" "0\0" "0\0,\0" "1\0\n\0";
    write_file(path, nobom, sizeof nobom - 1);
    expect(ctx, path, LX_INPUT_SPECTRUM, LX_EPARSE, "UTF-16 text (little-endian, no byte-order mark)", 1);
    /* control bytes: many are binary; a few, BEL/BS/ESC and a DOS end-of-file ^Z are text */
    for (size_t i = 0; i < sizeof b; i++) b[i] = (unsigned char)(i % 64 == 63 ? '\n' : 'a' + i % 26);
    for (size_t i = 0; i < 100; i++) b[37 * i + 5] = 0x01 + (unsigned char)(i % 5);
    write_file(path, b, sizeof b);
    expect(ctx, path, LX_INPUT_LUMINAIRE, LX_EPARSE, "binary data (100 control bytes in the first 8192, the first 0x01 at offset 5)", 1);
    for (size_t i = 0; i < 100; i++) b[37 * i + 5] = 'q';
    b[10] = 0x02, b[20] = 0x1f, b[30] = 0x07, b[40] = 0x08, b[50] = 0x1b, b[sizeof b - 1] = 0x1a;
    write_file(path, b, sizeof b);
    expect(ctx, path, LX_INPUT_LUMINAIRE, LX_OK, NULL, 0);
    for (size_t i = 0; i < sizeof b; i++) b[i] = (unsigned char)(0x80 + i % 128); /* Latin-1 / UTF-8 bytes */
    write_file(path, b, sizeof b);
    expect(ctx, path, LX_INPUT_SPECTRUM, LX_OK, NULL, 0);
    expect(ctx, path, LX_INPUT_SPECTRUM, LX_OK, NULL, 0);
    /* the mapped-text check of the batch reader is the same rule */
    assert_int_equal(lx__text_check(ctx, "mem", "ab\n\0", 4), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 2);
    lx_assert_ok(ctx, lx__text_check(ctx, "mem", "ab\ncd", 5));
    lx_assert_ok(ctx, lx__input_size_check(ctx, "f", LX_INPUT_SCENE, (unsigned long long)16 << 20));
    assert_int_equal(lx__input_size_check(ctx, "f", LX_INPUT_SCENE, ((unsigned long long)16 << 20) + 1), LX_EIO);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "f: larger than 16 MB"));
}

/* Devices: /dev/zero and /dev/urandom never end; both are refused at once, from the first block. */
static void devices(void **state)
{
    lx_ctx *ctx = *state;
    if (access("/dev/zero", R_OK) != 0 || access("/dev/urandom", R_OK) != 0) {
        skip(); /* no such devices on this system */
        return;
    }
    double t0 = now_s();
    expect(ctx, "/dev/zero", LX_INPUT_SPECTRUM, LX_EPARSE, "binary data (NUL byte at offset 0)", 1);
    char *text = NULL;
    size_t len = 0;
    assert_int_equal(lx__read_all(ctx, "/dev/urandom", LX_INPUT_SCENE, &text, &len), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "not a text file"));
    assert_true(now_s() - t0 < 1.0);
}

/* A writer that never stops: "y\n" for ever into fd. */
static void writer(int fd)
{
    char buf[65536];
    for (size_t i = 0; i < sizeof buf; i += 2) buf[i] = 'y', buf[i + 1] = '\n';
    while (write(fd, buf, sizeof buf) > 0) continue; /* until the reader closes its end (EPIPE) */
    close(fd);
}

/* A FIFO fed for ever stops at the limit: memory stays the limit, the time what it takes to read it. */
static void endless_fifo(void **state)
{
    lx_ctx *ctx = *state;
    char path[128];
    snprintf(path, sizeof path, "%s/fifo", dir);
    assert_int_equal(mkfifo(path, 0600), 0);
    signal(SIGPIPE, SIG_IGN);
    lx_assert_ok(ctx, lx_ctx_set_input_limit(ctx, LX_INPUT_SPECTRUM, (size_t)4 << 20));
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) { /* the writer process: opens the FIFO (blocks until the reader), writes for ever */
        int f = open(path, O_WRONLY);
        if (f < 0) _exit(1);
        writer(f);
        _exit(0);
    }
    double t0 = now_s();
    expect(ctx, path, LX_INPUT_SPECTRUM, LX_EIO, "larger than 4 MB, the limit for a spectrum file", 0);
    double dt = now_s() - t0;
    kill(pid, SIGTERM);
    int status;
    waitpid(pid, &status, 0);
    assert_true(dt < 5.0); /* 4 MB through a pipe: milliseconds; generous for a loaded machine */
    unlink(path);
}

static int setup_dir(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/lxreadXXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown_dir(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(limits_and_settings, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(regular_file_limit, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(binary_input, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(devices, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(endless_fifo, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
