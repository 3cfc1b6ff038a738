/* SPDX-License-Identifier: MIT OR Apache-2.0 */
/* phong_kit: run your C shading code on phong-approx's published test vectors.
 *
 * You write one function that shades a scan-line span; the kit reads a set's
 * inputs (vectors/SET-inputs.csv), calls your function once per case, and writes
 * the results CSV that `phong-approx check` judges:
 *
 *     #include "phong_kit.h"
 *
 *     static int shade(const pk_case_f32 *c, float *out, void *user) {
 *         ... write out[0], ..., out[c->n] ...
 *         return 0;
 *     }
 *
 *     int main(int argc, char **argv) {
 *         return pk_main(argc, argv, shade, NULL, NULL);
 *     }
 *
 *     cc -O2 -std=c99 -o mine mine.c phong_kit.c -lm
 *     ./mine vectors/typical-inputs.csv > typical.csv
 *     phong-approx check --vectors vectors/typical.json --results typical.csv \
 *         --method corrected-euler
 *
 * harness/c/run.sh does all of that for every published set, with and without
 * fused multiply-adds. C99 and its standard library only; memory: a line buffer of
 * PK_MAX_LINE bytes and one buffer of n + 1 values.
 *
 * THE INPUTS. Each case is a span of n + 1 pixels i = 0..n between two unit normals
 * N_a and N_b, lit by a unit vector L; the normal at pixel i is
 * N(i) = N_a + i·(N_b − N_a)/n (not normalized). The vector files give every input as
 * an exact fraction; the kit hands your function the nearest float (pk_case_f32) or
 * the nearest double (pk_case_f64) of each, read bit for bit from the hex columns
 * (`na_x_f32` = 0x + 8 hex digits of the binary32, `na_x_f64` = 0x + 16 hex digits of
 * the binary64). The exact fractions are not parsed. Those are the inputs the
 * checker's tolerances assume: do not normalize them again.
 *
 * THE OUTPUT. Your function writes the method's n + 1 values, out[i] for pixel i,
 * into `out` (room for exactly n + 1 values; the kit fills it with NaN first, so a
 * value you leave unwritten fails its pixel) and returns 0. The kit prints them as
 * `case,pixel,value` rows, floats with %.9g and doubles with %.17g, which read back
 * to the same float or double. Return non-zero to stop the run (the kit then says
 * which case, and returns PK_SHADE_FAILED).
 *
 * SPECULAR. Cases with a specular part (has_specular = 1) also carry a unit half
 * vector H and a shininess s. By default (part = PK_DIFFUSE) every case is handed
 * over and the function computes the method along the span with L. With
 * PK_SPECULAR (`--specular` to pk_main) only the cases with a specular part are,
 * with part = PK_SPECULAR, and the function writes max(0, method(N(i)·H))^s: the
 * method run with H in place of L, then the power. Check those results with
 * `phong-approx check --specular`.
 *
 * LIMITS AND ERRORS. Lines of at most PK_MAX_LINE bytes, at most PK_MAX_COLUMNS
 * columns, 1 <= n <= PK_MAX_STEPS (so the kit's one buffer is at most 8 MiB), case
 * ids of at most PK_MAX_ID bytes without control characters or quotes, non-finite
 * bit patterns refused. The columns are found by their names in the header line (a
 * UTF-8 byte-order mark and CRLF line ends are accepted; blank lines are skipped),
 * so columns the kit does not read may come and go. Any problem stops the run with
 * one line on stderr ("phong_kit: FILE:LINE: what") and a non-zero return, after
 * which the results written so far are incomplete; the kit never exits or aborts on
 * its own. A write that fails (on a full disk, say) is said with the system's
 * reason: "phong_kit: cannot write the results to <stdout>: No space left on
 * device".
 *
 * VERSION. PK_VERSION ("MAJOR.MINOR.PATCH") and PK_VERSION_MAJOR, _MINOR and _PATCH
 * are the version of the header you compiled against; pk_version() returns the
 * PK_VERSION of the phong_kit.c you linked, so a program can check that the two
 * agree (strcmp(pk_version(), PK_VERSION) == 0). The kit is versioned on its own,
 * not with the phong-approx crate. Its policy (semantic versioning):
 *   - Within 0.x, a minor bump (0.2 -> 0.3) may break the API or the behaviour; a
 *     patch bump (0.2.0 -> 0.2.1) never does. From 1.0 on only a major bump may.
 *   - An entry point (a function, type, macro or header) that is removed or
 *     renamed is kept for one more minor version as a deprecated wrapper, marked
 *     PK_DEPRECATED("use ... instead"): __attribute__((deprecated("..."))) under
 *     GCC and Clang, so that a build using it warns and names the replacement.
 *   - CHANGELOG.md, next to this file, names every change, version by version.
 * So exact_input.h (kit 0.1.0, removed in 0.2.0 when the kit started reading the
 * hex columns) is back in 0.2.x, deprecated: the old code compiles and gives the same
 * results, with a warning naming its replacement; it goes in 0.3.0.
 */
#ifndef PHONG_KIT_H
#define PHONG_KIT_H

#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The kit's version (see VERSION above): the header's, at compile time. */
#define PK_VERSION_MAJOR 0
#define PK_VERSION_MINOR 2
#define PK_VERSION_PATCH 0
#define PK_VERSION "0.2.0"

/* Marks a deprecated entry point: a use of it warns, with `msg` (the replacement),
 * under GCC and Clang; nothing elsewhere. */
#if defined(__GNUC__) || defined(__clang__)
#define PK_DEPRECATED(msg) __attribute__((deprecated(msg)))
#else
#define PK_DEPRECATED(msg)
#endif

#define PK_MAX_STEPS (1L << 20) /* largest n: spans of up to 2^20 + 1 pixels */
#define PK_MAX_LINE 16384       /* bytes per line of the inputs file, not counting its \n */
#define PK_MAX_COLUMNS 64       /* columns per line */
#define PK_MAX_ID 255           /* bytes of a case id */

/* Return values of pk_run_f32, pk_run_f64 and pk_main (the exit code). */
enum {
    PK_OK = 0,           /* every case shaded, the results written */
    PK_SHADE_FAILED = 1, /* the shading function returned non-zero */
    PK_BAD_INPUT = 2     /* bad arguments or input, or a read or write error */
};

/* What the shading function is asked for (pk_case_*.part). */
enum {
    PK_DIFFUSE = 0, /* the method's values along the span with L */
    PK_SPECULAR = 1 /* max(0, the method's value with H in place of L)^s */
};

/* One case, as the nearest binary32 of its exact inputs. */
typedef struct {
    const char *id;  /* the case id, e.g. "typical-001": the vector file's name for the
                        case, for your messages (valid during the call only) */
    long n;          /* steps: 1 <= n <= PK_MAX_STEPS; write out[0..n], n + 1 values */
    float na[3];     /* N_a, the unit normal at pixel 0 (x, y, z) */
    float nb[3];     /* N_b, the unit normal at pixel n */
    float l[3];      /* L, the unit light vector */
    int has_specular; /* 1 if the case has a specular part: h and s below */
    float h[3];      /* H, the unit half vector (zeros when has_specular is 0) */
    uint32_t s;      /* the shininess s (0 when has_specular is 0) */
    int part;        /* PK_DIFFUSE or PK_SPECULAR: what to write */
} pk_case_f32;

/* The same case as the nearest binary64 of its exact inputs. */
typedef struct {
    const char *id;
    long n;
    double na[3], nb[3], l[3];
    int has_specular;
    double h[3];
    uint32_t s;
    int part;
} pk_case_f64;

/* Your shading function: write out[0..c->n] and return 0 (non-zero stops the run).
 * `user` is the pointer given to pk_run_* or pk_main, passed through untouched. */
typedef int (*pk_shade_f32)(const pk_case_f32 *c, float *out, void *user);
typedef int (*pk_shade_f64)(const pk_case_f64 *c, double *out, void *user);

/* Flags of pk_run_f32 and pk_run_f64. */
#define PK_FLAG_SPECULAR 1 /* hand over only the specular cases, part = PK_SPECULAR */

/* Reads an inputs CSV from `in` (named `in_name` in messages; NULL: "<input>"),
 * calls `shade` once per case in file order, and writes the results CSV, header
 * `case,pixel,value` first, to `out`. Returns PK_OK, PK_SHADE_FAILED or
 * PK_BAD_INPUT (with one line on stderr). Neither stream is closed. */
int pk_run_f32(FILE *in, const char *in_name, FILE *out, int flags, pk_shade_f32 shade,
               void *user);
int pk_run_f64(FILE *in, const char *in_name, FILE *out, int flags, pk_shade_f64 shade,
               void *user);

/* A whole program's main: `return pk_main(argc, argv, shade32, shade64, user);`.
 * Give the function of each precision you implement, NULL for the other.
 *
 *     PROG [--precision f32|f64] [--specular] [INPUTS.csv | -] > RESULTS.csv
 *
 * Reads INPUTS.csv (standard input if absent or `-`) and writes the results to
 * standard output. --precision picks the function (default: f32 if given, else
 * f64); asking for one that is NULL is an error. Returns the exit code: PK_OK,
 * PK_SHADE_FAILED, or PK_BAD_INPUT for bad arguments, input or output; `-h` or
 * `--help` prints the usage and returns PK_OK (PK_BAD_INPUT if it cannot be
 * written). */
int pk_main(int argc, char **argv, pk_shade_f32 shade32, pk_shade_f64 shade64, void *user);

/* The PK_VERSION of the phong_kit.c linked in, e.g. "0.2.0" (a static string). */
const char *pk_version(void);

#ifdef __cplusplus
}
#endif

#endif
