/* SPDX-License-Identifier: MIT OR Apache-2.0 */
/* phong_kit: see phong_kit.h. C99. */
#include "phong_kit.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The kit reads a float from its bits by memcpy: it needs IEEE binary32 and
 * binary64 the size of uint32_t and uint64_t. */
typedef char pk_float_is_32_bits[sizeof(float) == sizeof(uint32_t) ? 1 : -1];
typedef char pk_double_is_64_bits[sizeof(double) == sizeof(uint64_t) ? 1 : -1];

/* The twelve input components, in the order of pk_case_*: na, nb, l, h (x, y, z). */
static const char *const vector_names[4] = {"na", "nb", "l", "h"};
static const char *const axis_names[3] = {"x", "y", "z"};

/* One row of the inputs file, both precisions, as bits. */
typedef struct {
    const char *id;
    long n;
    uint32_t b32[12];
    uint64_t b64[12];
    int has_specular;
    uint32_t s;
} row_t;

/* Where the columns the kit reads are. */
typedef struct {
    int columns; /* in the header */
    int id, n, s, c32[12], c64[12];
} layout_t;

typedef struct {
    FILE *in;
    const char *name;
    long line;
    size_t len;
    char buf[PK_MAX_LINE + 1];
} reader_t;

static void complain(const reader_t *r, const char *what) {
    fprintf(stderr, "phong_kit: %s:%ld: %s\n", r->name, r->line, what);
}

/* Reads the next line into r->buf without its line end: 1 a line, 0 the end of the
 * input, -1 an error (said). A line of more than PK_MAX_LINE bytes, a NUL byte or a
 * read error stops the reading. */
static int read_line(reader_t *r) {
    size_t len = 0;
    int ch = EOF;
    r->line++;
    while ((ch = getc(r->in)) != EOF) {
        if (ch == '\n') break;
        if (ch == '\0') { complain(r, "a NUL byte: not a text file"); return -1; }
        if (len == PK_MAX_LINE) {
            char what[80];
            snprintf(what, sizeof what, "a line longer than %d bytes", PK_MAX_LINE);
            complain(r, what);
            return -1;
        }
        r->buf[len++] = (char)ch;
    }
    if (ch == EOF && ferror(r->in)) {
        fprintf(stderr, "phong_kit: %s: read error: %s\n", r->name, strerror(errno));
        return -1;
    }
    if (ch == EOF && len == 0) return 0;
    if (len > 0 && r->buf[len - 1] == '\r') len--;
    r->buf[len] = '\0';
    r->len = len;
    return 1;
}

/* Splits r->buf at every comma (fields may be empty); returns how many fields, or
 * -1 if more than PK_MAX_COLUMNS. */
static int split(char *line, char *field[PK_MAX_COLUMNS]) {
    int k = 0;
    for (;;) {
        if (k == PK_MAX_COLUMNS) return -1;
        field[k++] = line;
        char *comma = strchr(line, ',');
        if (!comma) return k;
        *comma = '\0';
        line = comma + 1;
    }
}

static int find_column(char *const field[], int k, const char *name) {
    int at = -1;
    for (int i = 0; i < k; i++)
        if (!strcmp(field[i], name)) {
            if (at >= 0) return -2;
            at = i;
        }
    return at;
}

static int read_header(reader_t *r, layout_t *lay) {
    int got = read_line(r);
    if (got == 0) { complain(r, "empty file: no header line"); return 0; }
    if (got < 0) return 0;
    char *line = r->buf;
    if ((unsigned char)line[0] == 0xef && (unsigned char)line[1] == 0xbb &&
        (unsigned char)line[2] == 0xbf)
        line += 3;
    char *field[PK_MAX_COLUMNS];
    int k = split(line, field);
    if (k < 0) {
        char what[80];
        snprintf(what, sizeof what, "more than %d columns in the header", PK_MAX_COLUMNS);
        complain(r, what);
        return 0;
    }
    lay->columns = k;
    struct { const char *name; int *at; } want[3 + 24];
    char names[24][16];
    int w = 0;
    want[w].name = "case"; want[w++].at = &lay->id;
    want[w].name = "n"; want[w++].at = &lay->n;
    want[w].name = "s"; want[w++].at = &lay->s;
    for (int j = 0; j < 12; j++) {
        for (int p = 0; p < 2; p++) {
            char *nm = names[2 * j + p];
            snprintf(nm, sizeof names[0], "%s_%s_%s", vector_names[j / 3], axis_names[j % 3], p ? "f64" : "f32");
            want[w].name = nm;
            want[w++].at = p ? &lay->c64[j] : &lay->c32[j];
        }
    }
    for (int i = 0; i < w; i++) {
        int at = find_column(field, k, want[i].name);
        if (at < 0) {
            char what[120];
            snprintf(what, sizeof what, "%s column %s in the header%s",
                    at == -1 ? "no" : "a second", want[i].name,
                    at == -1 && i >= 3 ? " (an inputs file without the hex columns?)" : "");
            complain(r, what);
            return 0;
        }
        *want[i].at = at;
    }
    return 1;
}

/* "0x" and exactly `digits` hex digits. */
static int parse_hex(const char *s, int digits, uint64_t *out) {
    uint64_t v = 0;
    if (s[0] != '0' || s[1] != 'x') return 0;
    s += 2;
    for (int i = 0; i < digits; i++) {
        char c = s[i];
        int d;
        if (c >= '0' && c <= '9') d = c - '0';
        else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
        else if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
        else return 0;
        v = v << 4 | (uint64_t)d;
    }
    if (s[digits] != '\0') return 0;
    *out = v;
    return 1;
}

/* Decimal digits only, at most `max`. */
static int parse_count(const char *s, uint64_t max, uint64_t *out) {
    uint64_t v = 0;
    if (!*s) return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return 0;
        v = v * 10 + (uint64_t)(*s - '0');
        if (v > max) return 0;
    }
    *out = v;
    return 1;
}

static int valid_id(const char *s) {
    size_t len = strlen(s);
    if (len == 0 || len > PK_MAX_ID) return 0;
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c < 0x20 || c == 0x7f || c == '"') return 0;
    }
    return 1;
}

/* Parses the current line into *row: 1 done, 0 an error (said). */
static int parse_row(reader_t *r, const layout_t *lay, row_t *row) {
    char *field[PK_MAX_COLUMNS];
    char what[160];
    int k = split(r->buf, field);
    if (k != lay->columns) {
        if (k < 0) snprintf(what, sizeof what, "more than %d fields", PK_MAX_COLUMNS);
        else snprintf(what, sizeof what, "%d fields, the header has %d", k, lay->columns);
        complain(r, what);
        return 0;
    }
    if (!valid_id(field[lay->id])) {
        snprintf(what, sizeof what, "the case id is empty, longer than %d bytes, or has a control character or a quote", PK_MAX_ID);
        complain(r, what);
        return 0;
    }
    row->id = field[lay->id];
    uint64_t v;
    if (!parse_count(field[lay->n], (uint64_t)PK_MAX_STEPS, &v) || v < 1) {
        snprintf(what, sizeof what, "n is not a whole number from 1 to %ld", PK_MAX_STEPS);
        complain(r, what);
        return 0;
    }
    row->n = (long)v;
    /* The specular columns are all empty or all present. */
    int empty = field[lay->s][0] == '\0', full = !empty;
    for (int j = 9; j < 12; j++) {
        empty &= field[lay->c32[j]][0] == '\0' && field[lay->c64[j]][0] == '\0';
        full &= field[lay->c32[j]][0] != '\0' && field[lay->c64[j]][0] != '\0';
    }
    if (!empty && !full) {
        complain(r, "the specular columns (h_*_f32, h_*_f64, s) are neither all empty nor all given");
        return 0;
    }
    row->has_specular = full;
    row->s = 0;
    if (full) {
        if (!parse_count(field[lay->s], UINT32_MAX, &v)) {
            complain(r, "s is not a whole number from 0 to 4294967295");
            return 0;
        }
        row->s = (uint32_t)v;
    }
    for (int j = 0; j < (full ? 12 : 9); j++) {
        for (int p = 0; p < 2; p++) {
            const char *text = field[p ? lay->c64[j] : lay->c32[j]];
            int digits = p ? 16 : 8;
            int ok = parse_hex(text, digits, &v);
            /* An exponent of all ones: an infinity or a NaN, never an input. */
            if (ok) ok = p ? (v >> 52 & 0x7ff) != 0x7ff : (v >> 23 & 0xff) != 0xff;
            if (!ok) {
                snprintf(what, sizeof what, "column %s_%s_%s: %s", vector_names[j / 3], axis_names[j % 3],
                        p ? "f64" : "f32",
                        text[0] ? (p ? "not 0x and 16 hex digits of a finite double"
                                     : "not 0x and 8 hex digits of a finite float")
                                : "empty: no hex bits");
                complain(r, what);
                return 0;
            }
            if (p) row->b64[j] = v;
            else row->b32[j] = (uint32_t)v;
        }
    }
    for (int j = 9; !full && j < 12; j++) {
        row->b32[j] = 0;
        row->b64[j] = 0;
    }
    return 1;
}

/* The results stream, and the first write to it that failed with the system's reason
 * (errno right after the failing call; 0 if it gave none). Every write is checked, so
 * that a full disk or a closed pipe is said as such, not as a bare "write error". */
typedef struct {
    FILE *f;
    const char *who;  /* for messages: "phong_kit", or pk_main's program name */
    const char *what; /* for messages: "the results to <stdout>", "the results", ... */
    int failed;
    int err;
} writer_t;

/* Records a write's result: `result` is negative (fprintf, fputs) or EOF (fflush)
 * on failure. Call it right after the write, with errno cleared before it. */
static int wrote(writer_t *w, int result) {
    if (result < 0 && !w->failed) {
        w->failed = 1;
        w->err = errno;
    }
    return !w->failed;
}

/* Flushes the stream and says the first write failure, if any, in one line on stderr
 * ("phong_kit: cannot write the results to <stdout>: No space left on device"):
 * 1 all written, 0 not (said). The stream is not closed. */
static int finish_writing(writer_t *w) {
    if (!w->failed) {
        errno = 0;
        wrote(w, fflush(w->f));
    }
    if (!w->failed && ferror(w->f)) { /* an error before the kit's writes: no errno */
        w->failed = 1;
        w->err = 0;
    }
    if (!w->failed) return 1;
    fprintf(stderr, "%s: cannot write %s: %s\n", w->who, w->what,
            w->err ? strerror(w->err) : "a write error, with no reason given by the C library");
    return 0;
}

/* What one precision does with a row. */
typedef struct {
    int f64;
    pk_shade_f32 shade32;
    pk_shade_f64 shade64;
    void *user;
    void *buf; /* room for `cap` values */
    long cap;
} run_t;

/* Shades one row and writes its values; a write that fails is recorded in *out and
 * stops the writing (PK_OK is still returned: run_file says the failure). */
static int shade_row(run_t *run, const row_t *row, int part, writer_t *out) {
    long n = row->n;
    size_t size = run->f64 ? sizeof(double) : sizeof(float);
    if (n + 1 > run->cap) {
        void *grown = realloc(run->buf, (size_t)(n + 1) * size);
        if (!grown) {
            fprintf(stderr, "phong_kit: out of memory for a span of %ld pixels\n", n + 1);
            return PK_BAD_INPUT;
        }
        run->buf = grown;
        run->cap = n + 1;
    }
    int rc;
    if (run->f64) {
        pk_case_f64 c;
        double *v = run->buf;
        memset(&c, 0, sizeof c);
        c.id = row->id;
        c.n = n;
        for (int j = 0; j < 12; j++) {
            double *dst = j < 3 ? &c.na[j] : j < 6 ? &c.nb[j - 3] : j < 9 ? &c.l[j - 6] : &c.h[j - 9];
            memcpy(dst, &row->b64[j], sizeof *dst);
        }
        c.has_specular = row->has_specular;
        c.s = row->s;
        c.part = part;
        for (long i = 0; i <= n; i++) v[i] = (double)NAN;
        rc = run->shade64(&c, v, run->user);
        for (long i = 0; rc == 0 && i <= n; i++) {
            errno = 0;
            if (!wrote(out, v[i] != v[i] ? fprintf(out->f, "%s,%ld,nan\n", row->id, i)
                                         : fprintf(out->f, "%s,%ld,%.17g\n", row->id, i, v[i])))
                break;
        }
    } else {
        pk_case_f32 c;
        float *v = run->buf;
        memset(&c, 0, sizeof c);
        c.id = row->id;
        c.n = n;
        for (int j = 0; j < 12; j++) {
            float *dst = j < 3 ? &c.na[j] : j < 6 ? &c.nb[j - 3] : j < 9 ? &c.l[j - 6] : &c.h[j - 9];
            memcpy(dst, &row->b32[j], sizeof *dst);
        }
        c.has_specular = row->has_specular;
        c.s = row->s;
        c.part = part;
        for (long i = 0; i <= n; i++) v[i] = NAN;
        rc = run->shade32(&c, v, run->user);
        for (long i = 0; rc == 0 && i <= n; i++) {
            errno = 0;
            if (!wrote(out, v[i] != v[i]
                                ? fprintf(out->f, "%s,%ld,nan\n", row->id, i)
                                : fprintf(out->f, "%s,%ld,%.9g\n", row->id, i, (double)v[i])))
                break;
        }
    }
    if (rc != 0) {
        fprintf(stderr, "phong_kit: case %.80s: the shading function returned %d\n", row->id, rc);
        return PK_SHADE_FAILED;
    }
    return PK_OK;
}

/* `out_what` names the output in messages: "the results to <stdout>", "the results". */
static int run_file(FILE *in, const char *in_name, FILE *out_file, const char *out_what,
                    int flags, run_t *run) {
    reader_t *r = malloc(sizeof *r);
    layout_t lay;
    row_t row;
    writer_t out = {out_file, "phong_kit", out_what, 0, 0};
    int rc = PK_OK;
    if (!r) {
        fprintf(stderr, "phong_kit: out of memory\n");
        return PK_BAD_INPUT;
    }
    r->in = in;
    r->name = in_name ? in_name : "<input>";
    r->line = 0;
    if (!read_header(r, &lay)) {
        free(r);
        return PK_BAD_INPUT;
    }
    errno = 0;
    wrote(&out, fputs("case,pixel,value\n", out.f));
    while (!out.failed) {
        int got = read_line(r);
        if (got < 0) { rc = PK_BAD_INPUT; break; }
        if (got == 0) break;
        if (r->len == 0) continue; /* a blank line */
        if (!parse_row(r, &lay, &row)) { rc = PK_BAD_INPUT; break; }
        if ((flags & PK_FLAG_SPECULAR) && !row.has_specular) continue;
        rc = shade_row(run, &row, (flags & PK_FLAG_SPECULAR) ? PK_SPECULAR : PK_DIFFUSE, &out);
        if (rc != PK_OK) break;
    }
    free(r);
    free(run->buf);
    run->buf = NULL;
    run->cap = 0;
    if (!finish_writing(&out)) return PK_BAD_INPUT;
    return rc;
}

int pk_run_f32(FILE *in, const char *in_name, FILE *out, int flags, pk_shade_f32 shade,
               void *user) {
    run_t run = {0, shade, NULL, user, NULL, 0};
    if (!in || !out || !shade) {
        fprintf(stderr, "phong_kit: pk_run_f32 needs an input, an output and a function\n");
        return PK_BAD_INPUT;
    }
    return run_file(in, in_name, out, "the results", flags, &run);
}

int pk_run_f64(FILE *in, const char *in_name, FILE *out, int flags, pk_shade_f64 shade,
               void *user) {
    run_t run = {1, NULL, shade, user, NULL, 0};
    if (!in || !out || !shade) {
        fprintf(stderr, "phong_kit: pk_run_f64 needs an input, an output and a function\n");
        return PK_BAD_INPUT;
    }
    return run_file(in, in_name, out, "the results", flags, &run);
}

const char *pk_version(void) { return PK_VERSION; }

static int usage(FILE *to, const char *prog) {
    return fprintf(to,
                   "usage: %s [--precision f32|f64] [--specular] [INPUTS.csv | -] > RESULTS.csv\n",
                   prog);
}

int pk_main(int argc, char **argv, pk_shade_f32 shade32, pk_shade_f64 shade64, void *user) {
    const char *prog = argc > 0 && argv[0] && argv[0][0] ? argv[0] : "phong_kit";
    const char *path = NULL, *precision = NULL;
    int flags = 0, options = 1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (options && !strcmp(a, "--")) {
            options = 0;
        } else if (options && (!strcmp(a, "-h") || !strcmp(a, "--help"))) {
            writer_t w = {stdout, prog, "the usage to <stdout>", 0, 0};
            errno = 0;
            wrote(&w, usage(stdout, prog));
            return finish_writing(&w) ? PK_OK : PK_BAD_INPUT;
        } else if (options && !strcmp(a, "--precision")) {
            if (++i == argc) {
                fprintf(stderr, "%s: --precision needs f32 or f64\n", prog);
                return PK_BAD_INPUT;
            }
            precision = argv[i];
        } else if (options && !strncmp(a, "--precision=", 12)) {
            precision = a + 12;
        } else if (options && !strcmp(a, "--specular")) {
            flags |= PK_FLAG_SPECULAR;
        } else if (options && a[0] == '-' && a[1]) {
            fprintf(stderr, "%s: unknown option %.40s; ", prog, a);
            usage(stderr, prog);
            return PK_BAD_INPUT;
        } else if (path) {
            fprintf(stderr, "%s: one inputs file only; ", prog);
            usage(stderr, prog);
            return PK_BAD_INPUT;
        } else {
            path = a;
        }
    }
    int f64;
    if (!precision) {
        f64 = !shade32;
    } else if (!strcmp(precision, "f32") || !strcmp(precision, "f64")) {
        f64 = precision[1] == '6';
    } else {
        fprintf(stderr, "%s: --precision takes f32 or f64, not %.40s\n", prog, precision);
        return PK_BAD_INPUT;
    }
    if (f64 ? !shade64 : !shade32) {
        fprintf(stderr, "%s: this program has no %s shading function (pk_main got NULL)\n",
                prog, f64 ? "f64" : "f32");
        return PK_BAD_INPUT;
    }
    FILE *in = stdin;
    const char *name = "<stdin>";
    if (path && strcmp(path, "-")) {
        in = fopen(path, "r");
        if (!in) {
            fprintf(stderr, "%s: cannot open %.200s: %s\n", prog, path, strerror(errno));
            return PK_BAD_INPUT;
        }
        name = path;
    }
    run_t run = {f64, shade32, shade64, user, NULL, 0};
    int rc = run_file(in, name, stdout, "the results to <stdout>", flags, &run);
    if (in != stdin) fclose(in);
    return rc;
}
