/*
 * The studio's text set-point lines, read one character at a time with no dynamic memory
 * (docs/PROTOCOL.md, "Text line form"):
 *
 *   S,seq,v1,v2,v3,v4,v5,v6   set-points, armed
 *   E,seq                     emergency stop: stop at once
 *   H,seq,v1,v2,v3,v4,v5,v6   returning home after a stop: follow the values
 *
 * Values are whole numbers in the link's unit (with `link.output = "pulse"`: servo pulse
 * widths in microseconds). Header only, C99 and C++ (the Arduino IDE compiles sketches as
 * C++); the host tests build it with the system C compiler.
 *
 *   stewart_text_reader r;
 *   stewart_text_init(&r);
 *   stewart_text_line line;
 *   if (stewart_text_push(&r, c, &line) == STEWART_TEXT_LINE) { ... use line ... }
 */
#ifndef STEWART_TEXT_H
#define STEWART_TEXT_H

#include <stdint.h>

#define STEWART_TEXT_MAX_LINE 96

/* What stewart_text_push says about the character it took. */
#define STEWART_TEXT_NONE 0  /* nothing yet */
#define STEWART_TEXT_LINE 1  /* a whole, well-formed line is in *out */
#define STEWART_TEXT_BAD (-1) /* a line that was too long or not of the form above: dropped */

typedef struct {
    char line[STEWART_TEXT_MAX_LINE];
    uint8_t len;
    uint8_t overflow;
} stewart_text_reader;

typedef struct {
    char kind;          /* 'S', 'E' or 'H' */
    uint16_t sequence;
    int32_t values[6];  /* zero for 'E' */
} stewart_text_line;

static void stewart_text_init(stewart_text_reader *r) {
    r->len = 0;
    r->overflow = 0;
}

/* Reads a decimal integer from *p within [lo, hi]; moves *p past it. */
static int stewart_text_number(const char **p, int64_t lo, int64_t hi, int64_t *out) {
    const char *s = *p;
    int negative = 0;
    int64_t v = 0;
    int digits = 0;
    if (*s == '-') {
        negative = 1;
        s++;
    }
    while (*s >= '0' && *s <= '9') {
        v = v * 10 + (*s - '0');
        if (v > 4294967296LL) {
            return 0;
        }
        s++;
        digits++;
    }
    if (digits == 0) {
        return 0;
    }
    if (negative) {
        v = -v;
    }
    if (v < lo || v > hi) {
        return 0;
    }
    *out = v;
    *p = s;
    return 1;
}

static int stewart_text_parse(const char *s, stewart_text_line *out) {
    int64_t v;
    int k;
    int count;
    if (s[0] != 'S' && s[0] != 'E' && s[0] != 'H') {
        return STEWART_TEXT_BAD;
    }
    out->kind = s[0];
    s++;
    if (*s++ != ',' || !stewart_text_number(&s, 0, 65535, &v)) {
        return STEWART_TEXT_BAD;
    }
    out->sequence = (uint16_t)v;
    count = out->kind == 'E' ? 0 : 6;
    for (k = 0; k < 6; k++) {
        out->values[k] = 0;
    }
    for (k = 0; k < count; k++) {
        if (*s++ != ',' || !stewart_text_number(&s, -2147483647LL - 1, 2147483647LL, &v)) {
            return STEWART_TEXT_BAD;
        }
        out->values[k] = (int32_t)v;
    }
    return *s == '\0' ? STEWART_TEXT_LINE : STEWART_TEXT_BAD;
}

static int stewart_text_push(stewart_text_reader *r, char c, stewart_text_line *out) {
    if (c == '\r') {
        return STEWART_TEXT_NONE;
    }
    if (c != '\n') {
        if (r->len + 1 >= STEWART_TEXT_MAX_LINE) {
            r->overflow = 1;
        } else {
            r->line[r->len++] = c;
        }
        return STEWART_TEXT_NONE;
    }
    {
        int result;
        r->line[r->len] = '\0';
        result = (r->overflow || r->len == 0) ? STEWART_TEXT_BAD : stewart_text_parse(r->line, out);
        r->len = 0;
        r->overflow = 0;
        return result;
    }
}

#endif
