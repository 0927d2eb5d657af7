// Six hobby servos driven by the Stewart-platform studio over USB serial.
//
// The studio sends one text line per set-point (docs/PROTOCOL.md): servo pulse widths in
// microseconds. Scenario settings for this sketch:
//
//   [actuator]  kind = "rotary" (with your horn, rod and joint numbers)
//   [link]
//   transport = "serial"
//   port = "/dev/ttyACM0"   # or COM3; `stewart link --list-ports`
//   baud = 115200
//   format = "text"
//   output = "pulse"
//   pulse_zero_us = 1500    # pulse at 0° of your servos
//   pulse_us_per_deg = 10   # about 10 µs per degree for most hobby servos
//   rate_hz = 50            # servos take a new pulse every 20 ms anyway
//
// Then: stewart link --scenario my-platform.toml   (or Connect / ARM in the viewer).
//
// Safety on this side too: every pulse is clamped to PULSE_MIN..PULSE_MAX; an `E` line
// stops the servos where they are; when no line has come for WATCHDOG_MS the servos stop
// where they are until the next good line. The board's LED is lit while set-points flow. Wire the servos' power separately from the
// board's 5 V (six servos draw amps), with a common ground.

#include <Servo.h>

#include "stewart_text.h"

const uint8_t PINS[6] = {3, 5, 6, 9, 10, 11};  // servo 1..6 signal pins
const int PULSE_MIN[6] = {900, 900, 900, 900, 900, 900};        // µs: mechanical ends of
const int PULSE_MAX[6] = {2100, 2100, 2100, 2100, 2100, 2100};  // your horns, measured
const int PULSE_START = 1500;                   // µs at power-up (the studio's home, 0°)
const unsigned long WATCHDOG_MS = 250;

Servo servos[6];
stewart_text_reader reader;
unsigned long last_line_ms = 0;
bool moving = false;
unsigned long lines = 0, bad = 0, lost = 0;
long last_sequence = -1;

static int clamp_pulse(int k, long v) {
  if (v < PULSE_MIN[k]) return PULSE_MIN[k];
  if (v > PULSE_MAX[k]) return PULSE_MAX[k];
  return (int)v;
}

void setup() {
  Serial.begin(115200);
  pinMode(LED_BUILTIN, OUTPUT);
  stewart_text_init(&reader);
  for (int k = 0; k < 6; k++) {
    servos[k].attach(PINS[k]);
    servos[k].writeMicroseconds(clamp_pulse(k, PULSE_START));
  }
}

void loop() {
  while (Serial.available() > 0) {
    stewart_text_line line;
    int r = stewart_text_push(&reader, (char)Serial.read(), &line);
    if (r == STEWART_TEXT_BAD) {
      bad++;
    }
    if (r != STEWART_TEXT_LINE) {
      continue;
    }
    lines++;
    if (last_sequence >= 0) {
      lost += (uint16_t)(line.sequence - (uint16_t)last_sequence - 1);
    }
    last_sequence = line.sequence;
    last_line_ms = millis();
    if (line.kind == 'E') {
      moving = false;  // stop at once: keep the pulses where they are
      continue;
    }
    moving = true;     // 'S' and 'H' lines: go to the values
    for (int k = 0; k < 6; k++) {
      servos[k].writeMicroseconds(clamp_pulse(k, line.values[k]));
    }
  }
  if (moving && millis() - last_line_ms > WATCHDOG_MS) {
    moving = false;    // the host went quiet: hold where we are
  }
  digitalWrite(LED_BUILTIN, moving ? HIGH : LOW);
}
