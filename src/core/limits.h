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

#endif /* LX_LIMITS_H */
