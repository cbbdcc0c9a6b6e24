/* lighting.h - helpers shared by the lighting commands (point, spot, disk, rect, convert, solve):
 * quantity options with units, the efficacy options, writing one result table. */
#ifndef LX_CLI_LIGHTING_H
#define LX_CLI_LIGHTING_H

#include "cli.h"

/* Parses option `opt` (e.g. "--distance") of quantity q; a bare number takes bare_unit (NULL: SI).
 * When photometric q is given in its radiometric counterpart (W, W/sr, W/m2, W/sr/m2) and
 * efficacy > 0 it is converted; without an efficacy that is an error saying to give one.
 * Prints the error and returns CLI_USAGE; 0 on success. */
int lt_quantity(lx_ctx *ctx, const char *cmd, const char *opt, const char *text, lx_quantity q,
                const char *bare_unit, double efficacy, double *out);

/* Parses n lengths separated by the characters of seps in turn (",," for X,Y,Z; ":,:" for
 * A0:A1,B0:B1): each may carry its unit ("2m", "6.5ft"); a unit after the last applies to the bare
 * ones before it ("6,4,9 ft", as in scene files); bare numbers alone are metres. Prints the error
 * naming opt (expect says what is expected) and returns CLI_USAGE; 0 on success. */
int lt_lengths(lx_ctx *ctx, const char *cmd, const char *opt, const char *text, const char *seps, const char *expect,
               double *out);

/* Resolves --efficacy TEXT or --spd FILE (at most one; both NULL gives 0 = none) into *efficacy
 * in lm/W. Returns 0, or the exit code after printing the error. */
int lt_efficacy(lx_ctx *ctx, const char *cmd, const char *eff_text, const char *spd_path, double *efficacy);

/* Writes the table in the chosen format to -o FILE (atomic) or stdout; returns the exit code. */
int lt_write(const char *cmd, cli_table *t, cli_format fmt, const char *out_path);

/* Parses --format; prints and returns -1 on a bad value. */
int lt_format(const char *cmd, const char *s, cli_format *fmt);

/* ---- the options every lighting command shares: --efficacy K, --spd FILE, --format F, -o FILE,
 * --help. A command's option table ends with LT_COMMON_LONGOPTS (then {0, 0, 0, 0}); it calls
 * lt_common_init before its getopt loop, passes the codes it does not handle itself to
 * lt_common_opt, and writes its result with lt_emit. */
#define LT_COMMON_LONGOPTS                                                                                             \
    {"efficacy", required_argument, 0, 'K'}, {"spd", required_argument, 0, 'S'},                                    \
        {"format", required_argument, 0, 'f'}, {"help", no_argument, 0, 'h'}
/* getopt_long's short options of every lighting command: -o FILE and -h */
#define LT_SHORTOPTS ":o:h"
/* lt_common_opt's "handled, go on parsing" */
#define LT_NEXT (-1)

typedef struct lt_common {
    const char *cmd;  /* command name, as in the error messages */
    const char *help; /* the --help text */
    const char *eff, *spd, *out; /* --efficacy, --spd, -o (NULL: not given) */
    cli_format fmt;              /* --format (default table) */
    double efficacy;             /* lm/W from --efficacy or --spd (0: none), set by lt_start */
} lt_common;

/* Sets co to the defaults for command cmd with help text help and restarts getopt (optind = 1,
 * no getopt messages). */
void lt_common_init(lt_common *co, const char *cmd, const char *help);

/* Handles the option code c from getopt_long that the command does not handle itself: a common
 * option is stored in co (LT_NEXT); --help prints co->help (CLI_OK); a bad --format value or
 * anything else prints the error (CLI_USAGE). Returns LT_NEXT or the exit code to return. */
int lt_common_opt(lt_common *co, int c, char **argv);

/* Prints "luxcalc CMD: unknown option 'ARG' (see luxcalc CMD --help)" (or "needs a value" for
 * c == ':') for the option getopt_long just read; returns CLI_USAGE. */
int lt_bad_option(const lt_common *co, char **argv, int c);

/* For commands without operands: prints "unexpected argument" and returns CLI_USAGE when
 * argv[optind] exists, else returns 0. */
int lt_no_operands(const lt_common *co, int argc, char **argv);

/* Creates the context (*ctx; NULL and CLI_RUNTIME when that fails) and resolves the efficacy
 * options into co->efficacy. Returns 0 or the exit code; the caller destroys a non-NULL *ctx. */
int lt_start(lt_common *co, lx_ctx **ctx);

/* Writes t in co->fmt to co->out (atomic) or stdout and frees t; returns the exit code. */
int lt_emit(const lt_common *co, cli_table *t);

/* lt_emit of one row of n numbers named names (units: the table format's unit labels). */
int lt_emit_nums(const lt_common *co, int n, const char *const *names, const char *const *units,
                 const double *vals);

/* radians to degrees as value / (pi/180), the same division the unit table uses */
#define LT_DEG (CLI_PI / 180.0)

/* An input echoed back after a unit conversion, as it was given: rounded to 15 significant digits,
 * which removes the conversion's last-bit residue (30deg -> 0.5235987755982988 rad -> 30, not
 * 29.999999999999996) and keeps every digit a user types. */
double lt_echo(double v);

#endif
