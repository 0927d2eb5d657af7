/* See stewart_link.h and docs/PROTOCOL.md. */
#include "stewart_link.h"

uint16_t stewart_crc16(const uint8_t *bytes, size_t n) {
    uint16_t crc = 0xFFFF;
    while (n--) {
        crc ^= (uint16_t)((uint16_t)(*bytes++) << 8);
        for (int k = 0; k < 8; k++) {
            crc = (crc & 0x8000) ? (uint16_t)((crc << 1) ^ 0x1021) : (uint16_t)(crc << 1);
        }
    }
    return crc;
}

void stewart_decoder_init(stewart_decoder *d) {
    d->filled = 0;
    d->have_sequence = 0;
    d->last_sequence = 0;
    d->lost = 0;
    d->bad = 0;
}

static uint16_t read_u16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }

static int32_t read_i32(const uint8_t *p) {
    uint32_t u = (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
    return (int32_t)u;
}

/* Check and unpack a full buffer. */
static int check(stewart_decoder *d, stewart_frame *out) {
    const uint8_t *b = d->buffer;
    if (stewart_crc16(b + 2, 30) != read_u16(b + 32)) return STEWART_BAD_CRC;
    if (b[2] != STEWART_VERSION) return STEWART_BAD_FIELD;
    if (b[3] != STEWART_KIND_SETPOINT && b[3] != STEWART_KIND_TELEMETRY) return STEWART_BAD_FIELD;
    if (b[6] & 0xF8) return STEWART_BAD_FIELD;
    if (b[7] > STEWART_UNIT_PULSE_US) return STEWART_BAD_FIELD;
    out->kind = b[3];
    out->sequence = read_u16(b + 4);
    out->flags = b[6];
    out->unit = b[7];
    for (int k = 0; k < 6; k++) out->values[k] = read_i32(b + 8 + 4 * k);
    if (out->kind == STEWART_KIND_SETPOINT) {
        if (d->have_sequence) {
            d->lost += (uint16_t)(out->sequence - d->last_sequence - 1);
        }
        d->have_sequence = 1;
        d->last_sequence = out->sequence;
    }
    return STEWART_FRAME;
}

int stewart_decoder_push(stewart_decoder *d, uint8_t byte, stewart_frame *out) {
    if (d->filled == 0 && byte != 0xA5) return STEWART_NONE;
    if (d->filled == 1 && byte != 0x5A) {
        d->filled = (byte == 0xA5) ? 1 : 0;
        return STEWART_NONE;
    }
    d->buffer[d->filled++] = byte;
    if (d->filled < STEWART_FRAME_LEN) return STEWART_NONE;
    int status = check(d, out);
    d->filled = 0;
    if (status != STEWART_FRAME) {
        d->bad++;
        /* Keep what follows the next sync candidate inside the dropped bytes. */
        for (int j = 1; j < STEWART_FRAME_LEN; j++) {
            if (d->buffer[j] == 0xA5 && (j + 1 == STEWART_FRAME_LEN || d->buffer[j + 1] == 0x5A)) {
                for (int k = j; k < STEWART_FRAME_LEN; k++) d->buffer[k - j] = d->buffer[k];
                d->filled = (uint8_t)(STEWART_FRAME_LEN - j);
                break;
            }
        }
    }
    return status;
}

static void write_u16(uint8_t *p, uint16_t v) {
    p[0] = (uint8_t)(v & 0xFF);
    p[1] = (uint8_t)(v >> 8);
}

void stewart_encode(const stewart_frame *f, uint8_t out[STEWART_FRAME_LEN]) {
    out[0] = 0xA5;
    out[1] = 0x5A;
    out[2] = STEWART_VERSION;
    out[3] = f->kind;
    write_u16(out + 4, f->sequence);
    out[6] = f->flags;
    out[7] = f->unit;
    for (int k = 0; k < 6; k++) {
        uint32_t u = (uint32_t)f->values[k];
        out[8 + 4 * k] = (uint8_t)(u & 0xFF);
        out[9 + 4 * k] = (uint8_t)((u >> 8) & 0xFF);
        out[10 + 4 * k] = (uint8_t)((u >> 16) & 0xFF);
        out[11 + 4 * k] = (uint8_t)(u >> 24);
    }
    write_u16(out + 32, stewart_crc16(out + 2, 30));
}
