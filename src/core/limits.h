/* limits.h - every bound the library puts on its input, with its value, in one place (included by
 * core_private.h; never installed). README "Robustness" lists the same table for users: keep the
 * two in step. Bounds a user can change say how; the others change only here (rebuild). */
#ifndef LX_LIMITS_H
#define LX_LIMITS_H

/* ---- whole files (core/file_open.c: lx__read_all) ---- */
/* Size limits per input kind in MB (2^20 bytes): LX_MAX_INPUT_MB (every kind), luxcalc
 * --max-input-mb, or lx_ctx_set_input_limit change them. */
#define LX__MAX_SPECTRUM_MB 256  /* LX_INPUT_SPECTRUM: SPD text, CGATS, instrument exports */
#define LX__MAX_LUMINAIRE_MB 16  /* LX_INPUT_LUMINAIRE: IES, EULUMDAT, TILT tables */
#define LX__MAX_SCENE_MB 16      /* LX_INPUT_SCENE: a scene file, and each of its includes */
#define LX__MAX_KERNEL_MB 16     /* LX_INPUT_KERNEL: an OpenCL kernel source from LX_KERNEL_DIR */
#define LX__MAX_INPUT_MB_ENV 1048576 /* the largest LX_MAX_INPUT_MB accepted (1 TB) */
/* Bytes of the first block a text reader inspects for binary data (NUL bytes, a UTF-16 byte-order
 * mark or pattern, control bytes); NUL bytes are refused anywhere, as each block arrives. */
#define LX__TEXT_PROBE_BYTES 65536
/* Control bytes (other than tab, line ends, form feed, BEL, BS, ESC, SUB) that make a first block
 * binary: more than this many per thousand bytes, and at least LX__TEXT_CONTROL_MIN of them. */
#define LX__TEXT_CONTROL_PER_MILLE 10
#define LX__TEXT_CONTROL_MIN 4
/* Seconds a FIFO may take to deliver its first data (LX_FIFO_WAIT_S changes it; 0 waits for ever). */
#define LX__FIFO_WAIT_S 10

/* ---- the streamed batch CSV (spectral/batch_csv.c) ---- */
/* The longest line (the header or a row) of a rows-layout batch file read by lx_batch_table_read
 * or lx_batch_table_stream, in bytes: 4 MB holds a row of 200000 values of 20 characters. */
#define LX__BATCH_LINE_MAX ((size_t)4 << 20)

/* ---- luminaires (lighting/ies_read.c, lighting/ldt_read.c) ---- */
#define LX__IES_MAX_ANGLES 100000      /* vertical or horizontal angles of an IES table */
#define LX__IES_MAX_TILT_ANGLES 100000 /* angles of an IES TILT table */
#define LX__IES_MAX_LAMPS 1e6          /* the IES number of lamps */
#define LX__LDT_MAX_C_PLANES 3600      /* EULUMDAT Mc (0.1 deg steps) */
#define LX__LDT_MAX_GAMMA 18001        /* EULUMDAT Ng (0.01 deg steps over 0-180) */
#define LX__LDT_MAX_LAMP_SETS 20       /* EULUMDAT lamp sets */
#define LX__LDT_MAX_LAMPS 1e6          /* EULUMDAT lamps of one lamp set */

/* ---- scenes (scene/scene_read.c, scene/scene_entities.c) ---- */
#define LX__SCENE_MAX_DEPTH 16            /* nested includes */
#define LX__SCENE_MAX_LINE 1023           /* bytes of a scene line, comment excluded */
#define LX__SCENE_MAX_VALUE 511           /* bytes of a list value (position = x, y, z) */
#define LX__SCENE_MAX_POINTS_AXIS 100000  /* receiver points along one axis */
#define LX__SCENE_MAX_POINTS 10000000     /* points of one receiver */
#define LX__SCENE_MAX_SKY_SAMPLES 100000  /* [sky] samples */

/* ---- computations sized by input (lighting/grid.c, scene/scene_eval.c) ---- */
#define LX__NEAR_MAX_CELLS 512        /* near-field cells per side of a luminous area */
#define LX__GRID_MAX_TABLE_ROWS 16384 /* rows of a grid intensity table (--table-rows) */

/* ---- OpenEXR images (radiance/exr_io.c, radiance/spectral_exr.c) ---- */
/* A radiance map's display and data windows: at most LX__EXR_MAX_PIXELS pixels each, and at most
 * LX__EXR_PIXELS_FREE + LX__EXR_PIXELS_PER_BYTE x the file's size (beyond what real compression
 * reaches on real maps), checked before anything is sized by them. */
#define LX__EXR_MAX_PIXELS 1e9
#define LX__EXR_PIXELS_FREE 16777216.0
#define LX__EXR_PIXELS_PER_BYTE 64.0
/* A spectral image: values (pixels x spectral channels), the same way. */
#define LX__SPEXR_MAX_VALUES 4e9
#define LX__SPEXR_VALUES_FREE 1048576.0
#define LX__SPEXR_VALUES_PER_BYTE 64.0

#endif /* LX_LIMITS_H */
