/* cmd_bench.c - `luxcalc bench [TOPIC...]`: measured performance tables (markdown), one function
 * per topic in a table (src/cli/bench/), each topic's tables printed and, with --dir, written to
 * DIR/TOPIC.md under a header naming the date, the CPU and the SIMD path. */
#include "cli.h"

#include <getopt.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

typedef struct bench_ctx {
    FILE *out;       /* the markdown report (stdout or -o FILE) */
    size_t sizes[8]; /* --sizes */
    int nsizes;
    const char *tmp; /* scratch directory */
    const char *outpath; /* -o FILE (accuracy writes its PNG plots beside it) */
} bench_ctx;

int cli_bench_spd(FILE *out, const char *tmp, const size_t *sizes, int nsizes); /* bench_spd.c */
static int bench_spd(bench_ctx *b) { return cli_bench_spd(b->out, b->tmp, b->sizes, b->nsizes); }
int cli_bench_grid(FILE *out); /* bench_grid.c */
static int bench_grid(bench_ctx *b) { return cli_bench_grid(b->out); }
int cli_bench_metrics(FILE *out); /* bench_metrics.c */
static int bench_metrics(bench_ctx *b) { return cli_bench_metrics(b->out); }
int cli_bench_lab(FILE *out); /* bench_lab.c */
static int bench_lab(bench_ctx *b) { return cli_bench_lab(b->out); }

int cli_bench_irradiance(FILE *out); /* bench_irradiance.c */
static int bench_irradiance(bench_ctx *b) { return cli_bench_irradiance(b->out); }
int cli_bench_room(FILE *out); /* bench_room.c */
static int bench_room(bench_ctx *b) { return cli_bench_room(b->out); }
int cli_bench_daylight(FILE *out); /* bench_daylight.c */
static int bench_daylight(bench_ctx *b) { return cli_bench_daylight(b->out); }
int cli_bench_uncertainty(FILE *out, const char *tmp); /* bench_uncertainty.c */
static int bench_uncertainty(bench_ctx *b) { return cli_bench_uncertainty(b->out, b->tmp); }
int cli_bench_accuracy(FILE *out, const char *outpath); /* bench_accuracy.c */
static int bench_accuracy(bench_ctx *b) { return cli_bench_accuracy(b->out, b->outpath); }
static const struct {
    const char *name;
    int (*run)(bench_ctx *b);
    const char *summary;
} topics[] = {
    {"spd", bench_spd, "batch spectra -> XYZ V': in memory vs read bandwidth, CSV end to end vs peers"},
    {"metrics", bench_metrics, "CRI, TM-30 and alpha-opic per second over 1e5 spectra vs colour-science, luxpy"},
    {"lab", bench_lab, "PAR, IEC 62471 hazards and LED binning of 2.5e5 spectra on the batch path (goal 1e6/s)"},
    {"grid", bench_grid, "illuminance grid: 1e6 points x 10 luminaires, CPU and OpenCL vs numpy"},
    /* ---- bench topics (one line each: irradiance, grid, accuracy) ---- */
    {"accuracy", bench_accuracy, "error against a reference vs time of every method: spectra, radiance fields, lighting, near field"},
    {"irradiance", bench_irradiance, "irradiance maps: SH9, exact (fast), brute force vs numpy, 512x256..4096x2048"},
    {"room", bench_room, "interreflection: error of the work-plane mean and worst point against time, tolerance 1e-1..1e-4"},
    {"uncertainty", bench_uncertainty, "GUM and Monte Carlo of one 401-sample spectrum: 1e5 trials (goals 2 s, 20 s with Ra and Rf, GUM 50 ms) vs luxpy"},
    {"daylight", bench_daylight, "daylight factor in a 10 x 6 x 3 m room with two windows: error against a converged reference vs time"},
    {NULL, NULL, NULL},
};

static const char help[] =
    "usage: luxcalc bench [OPTIONS] [TOPIC...]\n"
    "\n"
    "Measures and prints performance tables as markdown (all topics when none is named), each topic\n"
    "under a header naming the date, the CPU model, its cores and the SIMD path in use.\n"
    "\n"
    "options:\n"
    "  --sizes N,N,...   batch sizes for spd (default 1e4,1e5,1e6)\n"
    "  --dir DIR         also write each topic to DIR/TOPIC.md (atomically; make bench: samples/bench)\n"
    "  -o FILE           also write all the tables to FILE (atomically)\n"
    "  -h, --help        this help\n"
    "\n"
    "environment: LX_SHARED_DIR (the peers' folder: LX_SHARED_DIR/peers, else ../shared/peers),\n"
    "LX_PEERS_PYTHON (a python with numpy and colour-science; default python3), LX_SIMD (caps the\n"
    "path; spd measures every path the CPU has in any case).\n"
    "\n"
    "example:\n"
    "  luxcalc bench spd --sizes 1e4,1e5 -o bench.md\n"
    "  luxcalc bench --dir samples/bench\n";

/* "AMD EPYC 9R45 ..." from /proc/cpuinfo ("unknown CPU" elsewhere) */
static void cpu_model(char *buf, size_t cap)
{
    snprintf(buf, cap, "unknown CPU");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f) return;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        char *c = strchr(line, ':');
        if (strncmp(line, "model name", 10) != 0 || !c) continue;
        c++;
        while (*c == ' ' || *c == '\t') c++;
        c[strcspn(c, "\n")] = 0;
        snprintf(buf, cap, "%s", c);
        break;
    }
    fclose(f);
}

/* The header of a topic's tables: what ran, when, on what. */
static void topic_header(FILE *o, const char *topic)
{
    char cpu[256], when[64];
    cpu_model(cpu, sizeof cpu);
    time_t now = time(NULL);
    struct tm tmv;
    gmtime_r(&now, &tmv);
    strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", &tmv);
    double load = -1;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &load) != 1) load = -1;
        fclose(f);
    }
    const char *cap = getenv("LX_SIMD");
    fprintf(o, "# luxcalc bench %s\n\n", topic);
    fprintf(o, "Measured %s by `luxcalc bench %s` (luxcalc %s) on %s, %ld cores online; SIMD path %s (the CPU's "
               "widest: %s%s%s%s)",
            when, topic, lx_version(), cpu, sysconf(_SC_NPROCESSORS_ONLN), lx_simd_name(lx_simd_level()),
            lx_simd_name(lx_simd_cpu()), cap && *cap ? "; LX_SIMD=" : "", cap && *cap ? cap : "", "");
    if (load >= 0) fprintf(o, "; load average %.2f at the start", load);
    fprintf(o, ".\n\n");
}

int cmd_bench(int argc, char **argv)
{
    static const struct option opts[] = {
        {"sizes", required_argument, NULL, 's'}, {"output", required_argument, NULL, 'o'},
        {"format", required_argument, NULL, 'f'}, {"dir", required_argument, NULL, 'd'},
        {"help", no_argument, NULL, 'h'},         {NULL, 0, NULL, 0},
    };
    bench_ctx b = {.out = stdout, .sizes = {10000, 100000, 1000000}, .nsizes = 3};
    const char *outpath = NULL, *dir = NULL;
    int c;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 's': {
            b.nsizes = 0;
            char *s = optarg, *e;
            while (*s && b.nsizes < 8) {
                double x = strtod(s, &e);
                if (e == s || !(x >= 1) || x > 1e8) return cli_error("bench", "--sizes: bad size in '%s'", optarg), CLI_USAGE;
                b.sizes[b.nsizes++] = (size_t)x;
                s = *e == ',' ? e + 1 : e;
                if (*e && *e != ',') return cli_error("bench", "--sizes: bad size in '%s'", optarg), CLI_USAGE;
            }
            break;
        }
        case 'o': outpath = b.outpath = optarg; break;
        case 'd': dir = optarg; break;
        case 'f': break; /* the report is markdown in every format */
        case 'h':
            cli_print_help(help);
            printf("\ntopics:\n");
            for (int i = 0; topics[i].name; i++) printf("  %-12s %s\n", topics[i].name, topics[i].summary);
            return CLI_OK;
        default: return cli_bad_option("bench", argv, c);
        }
    }
    for (int i = optind; i < argc; i++) {
        int found = 0;
        for (int t = 0; topics[t].name; t++) found |= !strcmp(argv[i], topics[t].name);
        if (!found) return cli_error("bench", "unknown topic '%s' (luxcalc bench --help lists them)", argv[i]), CLI_USAGE;
    }
    struct stat sb;
    if (dir && (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) && mkdir(dir, 0777) != 0)
        return cli_error("bench", "--dir %s: cannot create the directory", dir), CLI_USAGE;
    char tmp[] = "/tmp/luxcalc-bench-XXXXXX";
    if (!mkdtemp(tmp)) return cli_error("bench", "cannot create a scratch directory in /tmp"), CLI_RUNTIME;
    b.tmp = tmp;
    FILE *all = NULL; /* -o: every topic */
    char *allbuf = NULL;
    size_t alllen = 0;
    if (outpath && !(all = open_memstream(&allbuf, &alllen))) return CLI_RUNTIME;
    int rc = CLI_OK;
    for (int t = 0; topics[t].name; t++) {
        int wanted = optind >= argc;
        for (int i = optind; i < argc; i++) wanted |= !strcmp(argv[i], topics[t].name);
        if (!wanted) continue;
        /* each topic into memory, then to stdout, -o and DIR/TOPIC.md */
        char *buf = NULL;
        size_t len = 0;
        FILE *mem = open_memstream(&buf, &len);
        if (!mem) return CLI_RUNTIME;
        topic_header(mem, topics[t].name);
        b.out = mem;
        int r = topics[t].run(&b);
        if (r) rc = r;
        fclose(mem);
        fwrite(buf, 1, len, stdout);
        fflush(stdout);
        if (all) fwrite(buf, 1, len, all);
        if (dir && r == CLI_OK) {
            char path[1024];
            snprintf(path, sizeof path, "%s/%s.md", dir, topics[t].name);
            cli_output file = {0};
            if (cli_output_open(&file, path, "bench") == 0) {
                fwrite(buf, 1, len, file.fp);
                if (cli_output_close(&file, 1, "bench")) rc = CLI_RUNTIME;
            } else {
                rc = CLI_RUNTIME;
            }
        }
        free(buf);
    }
    rmdir(tmp);
    if (all) {
        fclose(all);
        cli_output file = {0};
        if (cli_output_open(&file, outpath, "bench") == 0) {
            fwrite(allbuf, 1, alllen, file.fp);
            if (cli_output_close(&file, 1, "bench")) rc = CLI_RUNTIME;
        } else {
            rc = CLI_RUNTIME;
        }
        free(allbuf);
    }
    return rc;
}
