/* Decoder (and encoder) of the Stewart platform studio's set-point frames, for
 * controllers: plain C99, no dynamic memory, no floating point. See docs/PROTOCOL.md.
 *
 *   stewart_decoder d;
 *   stewart_decoder_init(&d);
 *   for each received byte b:
 *       stewart_frame f;
 *       if (stewart_decoder_push(&d, b, &f) == STEWART_FRAME) { ... use f ... }
 */
#ifndef STEWART_LINK_H
#define STEWART_LINK_H

#include <stddef.h>
#include <stdint.h>

#define STEWART_FRAME_LEN 34
#define STEWART_VERSION 1

#define STEWART_KIND_SETPOINT 0x01
#define STEWART_KIND_TELEMETRY 0x02

#define STEWART_FLAG_ARMED 0x01
#define STEWART_FLAG_ESTOP 0x02
#define STEWART_FLAG_HOME 0x04

#define STEWART_UNIT_MICROMETRE 0x00   /* leg lengths */
#define STEWART_UNIT_CENTIDEGREE 0x01  /* servo angles, 0.01 degree */
#define STEWART_UNIT_PULSE_US 0x02     /* servo pulse widths */

/* What stewart_decoder_push says about the byte it took. */
#define STEWART_NONE 0          /* no frame complete yet */
#define STEWART_FRAME 1         /* *out holds a good frame */
#define STEWART_BAD_CRC (-1)    /* a frame's bytes were damaged: dropped */
#define STEWART_BAD_FIELD (-2)  /* version, kind, flags or unit not understood: dropped */

typedef struct {
    uint8_t kind;
    uint16_t sequence;
    uint8_t flags;
    uint8_t unit;
    int32_t values[6];
} stewart_frame;

typedef struct {
    uint8_t buffer[STEWART_FRAME_LEN];
    uint8_t filled;
    uint8_t have_sequence;  /* whether a set-point frame has been seen */
    uint16_t last_sequence; /* of the last good set-point frame */
    uint32_t lost;          /* set-point frames missing from the sequence so far */
    uint32_t bad;           /* frames dropped as damaged or not understood */
} stewart_decoder;

/* CRC-16/CCITT-FALSE: polynomial 0x1021, initial 0xFFFF, no reflection, no final XOR. */
uint16_t stewart_crc16(const uint8_t *bytes, size_t n);

void stewart_decoder_init(stewart_decoder *d);

/* Take one received byte; STEWART_FRAME when *out now holds a frame. */
int stewart_decoder_push(stewart_decoder *d, uint8_t byte, stewart_frame *out);

/* The 34 bytes of frame f (for telemetry back to the host). */
void stewart_encode(const stewart_frame *f, uint8_t out[STEWART_FRAME_LEN]);

#endif /* STEWART_LINK_H */
