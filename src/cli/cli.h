/* cli.h - shared pieces of the luxcalc command-line tool: the command table, result output as
 * table/csv/json, atomic output files, error reporting. Written only against luxcalc.h. */
#ifndef LX_CLI_H
#define LX_CLI_H

#include "luxcalc.h"

#include <stdio.h>

/* Exit codes (../shared/CLI.md). */
enum { CLI_OK = 0, CLI_USAGE = 1, CLI_INPUT = 2, CLI_RUNTIME = 3 };

typedef struct cli_cmd {
    const char *name;
    int (*run)(int argc, char **argv); /* argv[0] is the command name */
    const char *summary;
} cli_cmd;

extern const cli_cmd cli_commands[];

/* pi for the CLI (which sees only the public header; the library's constants are in
 * src/core/constants.h) */
#define CLI_PI 3.14159265358979323846

/* Global flags set by main before a command runs. */
extern int cli_verbose; /* -v: 1, -vv: 2 */
extern int cli_quiet;   /* -q */
extern size_t cli_max_input_mb; /* --max-input-mb N: every kind's input size limit (0: the library's) */

/* Parses a size limit in MB ("--max-input-mb", LX_MAX_INPUT_MB): a whole number from 1 to
 * CLI_MAX_INPUT_MB; returns 0 on success. */
#define CLI_MAX_INPUT_MB 1048576
int cli_parse_input_mb(const char *s, size_t *mb);

/* Prints "luxcalc: CMD: message" on stderr. */
void cli_error(const char *cmd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Prints the context's last error as "luxcalc: CMD: FILE:LINE: what" and returns the exit code
 * that fits the status (2 input, 3 runtime, 1 invalid usage). */
int cli_fail(const char *cmd, lx_ctx *ctx, lx_status st);

/* Maps a status to an exit code. */
int cli_exit_code(lx_status st);

/* A log callback that prints library messages on stderr when -v is given. */
void cli_log(void *user, lx_log_level level, const char *msg);

/* Creates a context with the CLI's log callback installed; prints and returns NULL on failure. */
lx_ctx *cli_ctx(const char *cmd);

/* ---- output formats ---- */
typedef enum cli_format { CLI_FMT_TABLE = 0, CLI_FMT_CSV, CLI_FMT_JSON, CLI_FMT_TSV } cli_format;

/* Parses "table", "csv", "tsv" or "json"; returns -1 for anything else. */
int cli_format_parse(const char *s);

/* ---- the output options of every command (format.c) ---- */
/* --precision N: significant digits of every number in the table format (0: each quantity's own:
 * x, y 5 decimals, CCT 0.1 K, Duv 1e-5, CRI and TM-30 0.1, lx/cd/lm/cd/m2 4 significant
 * digits, U0 3 decimals, lengths and angles to 1e-3; csv, tsv and json always round-trip). */
extern int cli_precision;
/* Takes --precision N and --units metric|imperial|UNIT[,UNIT...] (imperial: fc, ft, fL; a unit
 * name sets its quantity's output unit, e.g. cd/ft2) out of argv (argv[0] is the command);
 * a --units value that names no unit is left for the command. Returns 0 or CLI_USAGE (printed). */
int cli_output_options(const char *cmd, int *argc, char **argv);
/* "--distance 2 m" as two arguments: an option followed by a number and then a unit name becomes
 * the option and "2 m" (what the unit parser reads), as the documentation writes it. */
void cli_join_units(int *argc, char **argv);
/* 1 when illuminance goes out in fc and lengths in ft (the plots follow). */
int cli_imperial(void);
/* The luminance output unit ("cd/m2", "fL", ...) and the factor from cd/m2 into it. */
const char *cli_luminance_unit(double *scale);
/* A column as it goes out: its name with the unit suffix of the output unit ("illuminance_fc"),
 * that unit, and the factor from the column's own unit. */
typedef struct cli_column {
    char name[128];
    char unit[32];
    double scale;
} cli_column;
void cli_column_out(const char *name, const char *unit, cli_column *out);
/* A number of the column in the table format (rounded to the digits its quantity keeps). */
void cli_number_text(char *buf, size_t cap, const cli_column *col, double v);
/* For getopt_long's '?' (unknown) and ':' (a value missing; short options start with ':'): prints
 * "luxcalc CMD: unknown option '--x' (see luxcalc CMD --help)" or "luxcalc CMD: option '--x'
 * needs a value (see ...)" for the option just read; returns CLI_USAGE. */
int cli_bad_option(const char *cmd, char **argv, int c);
/* At start: when standard output is closed, fd 1 is held by a scratch file so that no file the
 * run opens becomes standard output. */
void cli_stdout_guard(void);
/* At the end of a command: standard output flushed; a write error (full disk, closed stdout) is
 * reported once as "luxcalc: CMD: stdout: REASON" and gives CLI_RUNTIME, else 0. */
int cli_stdout_check(const char *cmd);
/* Reports a failed write of path (NULL: stdout) with errno err once; returns CLI_RUNTIME. */
int cli_write_failed(const char *cmd, const char *path, int err);

/* A result table: named columns (with an optional unit shown in the table format), rows of
 * numbers or strings. NaN numbers print as empty (csv), null (json), "-" (table). */
typedef struct cli_table cli_table;
cli_table *cli_table_new(int ncols, const char *const *names, const char *const *units);
void cli_table_str(cli_table *t, const char *s);
void cli_table_num(cli_table *t, double v);
void cli_table_int(cli_table *t, long long v);
/* A number with its standard uncertainty and coverage interval: csv, tsv and json write v (the
 * interval goes in columns of its own), the table "v ± u unit [lo, hi]" to the column's digits. */
void cli_table_num_pm(cli_table *t, double v, double u, double lo, double hi);
/* Marks column col as left out of the table format (csv, tsv and json write it). */
void cli_table_not_in_table(cli_table *t, int col);
/* The number in column col of the row being filled (or, when none is, of the last row added);
 * returns -1 when that cell is not a number. */
int cli_table_cell_num(const cli_table *t, int col, double *v);
/* Appends to dst a copy of column col's cell of src's row being filled (or its last row). */
void cli_table_copy_cell(cli_table *dst, const cli_table *src, int col);
/* Forgets the rows added since the last flush, unwritten. */
void cli_table_discard(cli_table *t);
/* Writes every row (the header first) and ends the output. json_array: 1 prints an array even
 * for one row, 0 prints one object when there is exactly one row. Returns 0, or -1 on a write error. */
int cli_table_write(cli_table *t, cli_format fmt, FILE *out, int json_array);
/* Streams: writes the rows added since the last flush and forgets them (final = 1 ends the
 * output, as cli_table_write). For large batches, so results need not all sit in memory. */
int cli_table_flush(cli_table *t, cli_format fmt, FILE *out, int json_array, int final);
void cli_table_free(cli_table *t);
/* csv: writes the header line unless written already (other formats: nothing). 0, or -1 on a
 * write error. For rows a command writes itself (cli_csv_field, lx_double_format), which it then
 * counts with cli_table_count_written. */
int cli_table_header(cli_table *t, cli_format fmt, FILE *out);
/* 1 when the table's csv is its first n columns as they are (no unit scaling, no column left
 * out) and nothing more: a command writing rows itself may then write those n cells. */
int cli_table_plain_csv(cli_table *t, int n);
void cli_table_count_written(cli_table *t, size_t rows);
/* One csv cell of len bytes at s into dst (room for 2 len + 2), quoted as cli_table quotes it
 * (when it holds , " CR or LF; quotes doubled). Returns the end of what it wrote. */
char *cli_csv_field(char *dst, const char *s, size_t len);
int cli_table_rows(const cli_table *t); /* rows added so far, written or not */
/* A cell holding JSON text, written as it is in json (never NULL: "null" for none). */
void cli_table_json(cli_table *t, const char *json);
/* Marks column col as written in json only (csv and table leave it out). */
void cli_table_json_only(cli_table *t, int col);
/* Replaces the units shown in the table format for rows written from now on (flush first). */
void cli_table_set_units(cli_table *t, const char *const *units);
/* Writes s as a JSON string (quoted, escaped). */
void cli_json_string(FILE *out, const char *s);

/* Prints a double in the shortest form that reads back exactly (lx_double_format). */
void cli_print_exact(FILE *out, double v);

/* ---- atomic output: -o FILE ---- */
/* Opens FILE for writing through a temporary file in the same directory; "-" or NULL is stdout. */
typedef struct cli_output {
    FILE *fp;
    char *path; /* final path, NULL for stdout */
    char *tmp;  /* temporary path */
} cli_output;
int cli_output_open(cli_output *o, const char *path, const char *cmd);
/* Flushes, fsyncs and renames into place (ok = 1) or removes the temporary file (ok = 0). A
 * failed write ("No space left on device", a closed stdout) is reported as "luxcalc: CMD: FILE:
 * REASON" and returns CLI_RUNTIME (nothing half-written stays at FILE); else 0. A path that exists
 * and is not a regular file (/dev/null, a FIFO) is written directly. */
int cli_output_close(cli_output *o, int ok, const char *cmd);

/* ---- option helpers ---- */
/* Parses a whole string as a finite double; returns 0 on success. */
int cli_parse_double(const char *s, double *out);

/* File arguments with shell patterns expanded by luxcalc itself (for lists too long for the
 * shell, or shells that do not glob): an argument with * ? [ that is not an existing path and
 * matches files becomes those files, sorted; others stay as given. Free with cli_free_files. */
char **cli_expand_files(int n, char **args, int *nout);
void cli_free_files(char **files, int n);

/* Standard handling of --help for a command: prints usage text to stdout. */
void cli_print_help(const char *text);

#endif /* LX_CLI_H */
