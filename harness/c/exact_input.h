/* Exact inputs for C harnesses of phong-approx's published vectors.
 *
 * The vector files give every input as an exact fraction ("-775000/1179633"). Parsing
 * it as num/den in double and then converting to float rounds twice, and can miss
 * the nearest float. exact_input_f32 and exact_input_f64 round the exact fraction
 * once, to nearest with ties to even, with a small arbitrary-precision division:
 * the inputs a correct implementation is meant to read.
 *
 * Header-only, C99. Numerators and denominators of up to 300 decimal digits.
 */
#ifndef PHONG_APPROX_EXACT_INPUT_H
#define PHONG_APPROX_EXACT_INPUT_H

#include <stdint.h>
#include <string.h>
#include <math.h>

#define EXACT_LIMBS 40 /* 1280 bits: 300 decimal digits, shifted by up to 64 bits */

typedef struct { uint32_t w[EXACT_LIMBS]; } exact_big;

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

#endif
