/* SPDX-License-Identifier: MIT OR Apache-2.0 */
/* exact_input.h: DEPRECATED. A compatibility shim, kept for phong_kit 0.2.x only; it
 * goes in 0.3.0 (the policy: phong_kit.h, VERSION; the changes: CHANGELOG.md).
 *
 * Kit 0.1.0 had this header and harness.c: a C harness parsed the vector files'
 * exact fractions ("-775000/1179633") itself, and exact_input_f32 and
 * exact_input_f64 rounded each once to the nearest float or double. Since 0.2.0 the
 * inputs files carry those floats and doubles as hex bits, and phong_kit reads them:
 *
 *     exact_input_f32(text, &ok)   ->  pk_main or pk_run_f32: your pk_shade_f32 gets
 *                                      c->na, c->nb, c->l, c->h as these floats
 *     exact_input_f64(text, &ok)   ->  pk_main or pk_run_f64: pk_case_f64, doubles
 *     exact_input(text, mant, &ok) ->  the same, for mant = 24 or 53
 *
 * (phong_kit.h says how; harness/c/example_corrected_euler.c is a whole client.)
 * phong_kit parses no fraction, so this shim is not a wrapper over it: it keeps the
 * 0.1.0 code unchanged (header-only, static inline), and so the same results, bit
 * for bit: the exact fraction rounded once, to nearest with ties to even. Every
 * function is marked __attribute__((deprecated("..."))), as PK_DEPRECATED does, so
 * a use of it warns under GCC and Clang, naming the replacement;
 * `-Wno-deprecated-declarations` silences that while you move. The header stands
 * alone, as before (it needs neither phong_kit.h nor phong_kit.c), so the old build
 * line still works:
 *
 *     cc -O2 -o harness harness.c -lm
 *
 * C99. Numerators and denominators of up to 300 decimal digits.
 */
#ifndef PHONG_APPROX_EXACT_INPUT_H
#define PHONG_APPROX_EXACT_INPUT_H

#include <stdint.h>
#include <string.h>
#include <math.h>

#define EXACT_LIMBS 40 /* 1280 bits: 300 decimal digits, shifted by up to 64 bits */

/* The header's own uses of its deprecated functions do not warn; a client's do. */
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif

/* phong_kit.h's PK_DEPRECATED, defined here too: the header needs no other file. */
#if defined(__GNUC__) || defined(__clang__)
#define EXACT_INPUT_DEPRECATED(msg) __attribute__((deprecated(msg)))
#else
#define EXACT_INPUT_DEPRECATED(msg)
#endif
#define EXACT_INPUT_GONE "exact_input.h is deprecated and goes in phong_kit 0.3.0: "
#define EXACT_INPUT_INTERNAL \
    EXACT_INPUT_DEPRECATED(EXACT_INPUT_GONE "an internal of exact_input_f32/_f64, with no replacement")

typedef struct { uint32_t w[EXACT_LIMBS]; } exact_big;

/* The entry points, with their replacements. */
static inline float exact_input_f32(const char *text, int *ok)
    EXACT_INPUT_DEPRECATED(EXACT_INPUT_GONE "pk_main or pk_run_f32 reads the nearest floats from the "
                                            "*_f32 hex columns into pk_case_f32 (phong_kit.h)");
static inline double exact_input_f64(const char *text, int *ok)
    EXACT_INPUT_DEPRECATED(EXACT_INPUT_GONE "pk_main or pk_run_f64 reads the nearest doubles from the "
                                            "*_f64 hex columns into pk_case_f64 (phong_kit.h)");
static inline double exact_input(const char *text, int mant, int *ok)
    EXACT_INPUT_DEPRECATED(EXACT_INPUT_GONE "pk_run_f32 and pk_run_f64 read the nearest float (mant 24) "
                                            "and double (mant 53) from the hex columns (phong_kit.h)");
/* Its internals, which were visible too. */
static inline void exact_zero(exact_big *a) EXACT_INPUT_INTERNAL;
static inline int exact_is_zero(const exact_big *a) EXACT_INPUT_INTERNAL;
static inline void exact_mul_add(exact_big *a, uint32_t m, uint32_t c) EXACT_INPUT_INTERNAL;
static inline int exact_bits(const exact_big *a) EXACT_INPUT_INTERNAL;
static inline void exact_shl(exact_big *a, int s) EXACT_INPUT_INTERNAL;
static inline int exact_cmp(const exact_big *a, const exact_big *b) EXACT_INPUT_INTERNAL;
static inline void exact_sub(exact_big *a, const exact_big *b) EXACT_INPUT_INTERNAL;
static inline int exact_parse(exact_big *a, const char *s, const char *end) EXACT_INPUT_INTERNAL;
static inline double exact_round(exact_big num, exact_big den, int mant) EXACT_INPUT_INTERNAL;

/* From here on, kit 0.1.0's code (harness/c/exact_input.h at d555039), unchanged. */

static inline void exact_zero(exact_big *a) { memset(a, 0, sizeof *a); }

static inline int exact_is_zero(const exact_big *a) {
    for (int i = 0; i < EXACT_LIMBS; i++) if (a->w[i]) return 0;
    return 1;
}

/* a = a*m + c */
static inline void exact_mul_add(exact_big *a, uint32_t m, uint32_t c) {
    uint64_t carry = c;
    for (int i = 0; i < EXACT_LIMBS; i++) {
        uint64_t t = (uint64_t)a->w[i] * m + carry;
        a->w[i] = (uint32_t)t;
        carry = t >> 32;
    }
}

static inline int exact_bits(const exact_big *a) {
    for (int i = EXACT_LIMBS - 1; i >= 0; i--)
        if (a->w[i]) { int b = 32; while (!(a->w[i] >> (b - 1))) b--; return i * 32 + b; }
    return 0;
}

static inline void exact_shl(exact_big *a, int s) {
    exact_big r; exact_zero(&r);
    int limbs = s / 32, bits = s % 32;
    for (int i = EXACT_LIMBS - 1; i >= limbs; i--) {
        uint64_t v = (uint64_t)a->w[i - limbs] << bits;
        if (bits && i - limbs - 1 >= 0) v |= a->w[i - limbs - 1] >> (32 - bits);
        r.w[i] = (uint32_t)v;
    }
    *a = r;
}

static inline int exact_cmp(const exact_big *a, const exact_big *b) {
    for (int i = EXACT_LIMBS - 1; i >= 0; i--)
        if (a->w[i] != b->w[i]) return a->w[i] < b->w[i] ? -1 : 1;
    return 0;
}

static inline void exact_sub(exact_big *a, const exact_big *b) { /* a -= b, a >= b */
    int64_t borrow = 0;
    for (int i = 0; i < EXACT_LIMBS; i++) {
        int64_t t = (int64_t)a->w[i] - b->w[i] - borrow;
        borrow = t < 0;
        a->w[i] = (uint32_t)(t + (borrow ? ((int64_t)1 << 32) : 0));
    }
}

/* Parses decimal digits [s, end) into a; returns 0 on a non-digit. */
static inline int exact_parse(exact_big *a, const char *s, const char *end) {
    exact_zero(a);
    if (s == end) return 0;
    for (; s < end; s++) {
        if (*s < '0' || *s > '9') return 0;
        exact_mul_add(a, 10, (uint32_t)(*s - '0'));
    }
    return 1;
}

/* The nearest binary float with `mant` significand bits to num/den (> 0), as a
 * double holding it exactly (mant ≤ 53; no subnormal results). */
static inline double exact_round(exact_big num, exact_big den, int mant) {
    /* Scale num so that the quotient has mant + 2 bits: q = floor(num·2^s / den). */
    int e = exact_bits(&num) - exact_bits(&den); /* num/den in [2^(e-1), 2^(e+1)) */
    int s = mant + 2 - e;
    if (s > 0) exact_shl(&num, s); else if (s < 0) exact_shl(&den, -s);
    /* Long division, one bit at a time, of the mant + 3 top bits. */
    uint64_t q = 0;
    exact_big d = den;
    int top = 0;
    while (exact_cmp(&d, &num) <= 0) { exact_shl(&d, 1); top++; }
    for (int i = top - 1; i >= 0; i--) {
        exact_big t = den; exact_shl(&t, i);
        q <<= 1;
        if (exact_cmp(&num, &t) >= 0) { exact_sub(&num, &t); q |= 1; }
    }
    int sticky = !exact_is_zero(&num);
    /* q has mant + 2 or mant + 3 bits; keep mant, round to nearest even. */
    int qb = 0; while ((q >> qb) > 1) qb++; qb++;
    int drop = qb - mant;
    uint64_t keep = q >> drop;
    uint64_t rest = q & ((1ull << drop) - 1), half = 1ull << (drop - 1);
    if (rest > half || (rest == half && (sticky || (keep & 1)))) keep++;
    return ldexp((double)keep, drop - s);
}

/* "p/q", "p" or "-p/q" (decimal integers) to the nearest double with `mant` bits;
 * *ok = 0 when the text is not such a fraction. */
static inline double exact_input(const char *text, int mant, int *ok) {
    const char *s = text, *end = text + strcspn(text, ",\n\r");
    int neg = 0;
    *ok = 0;
    if (*s == '-') { neg = 1; s++; }
    const char *slash = memchr(s, '/', (size_t)(end - s));
    exact_big num, den;
    if (!exact_parse(&num, s, slash ? slash : end)) return 0.0;
    if (slash) { if (!exact_parse(&den, slash + 1, end)) return 0.0; }
    else { exact_zero(&den); den.w[0] = 1; }
    if (exact_is_zero(&den)) return 0.0;
    *ok = 1;
    if (exact_is_zero(&num)) return neg ? -0.0 : 0.0;
    double v = exact_round(num, den, mant);
    return neg ? -v : v;
}

static inline float exact_input_f32(const char *text, int *ok) { return (float)exact_input(text, 24, ok); }
static inline double exact_input_f64(const char *text, int *ok) { return exact_input(text, 53, ok); }

#undef EXACT_INPUT_INTERNAL
#undef EXACT_INPUT_GONE
#undef EXACT_INPUT_DEPRECATED

#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif

#endif
