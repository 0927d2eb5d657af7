#!/usr/bin/env python3
"""Write tests/cli/xplane_takeoff.txt: a takeoff as X-Plane's UDP `DATA` output would send
it, one datagram per line as `SECONDS HEX` (the time it is due, the bytes in hex).

Synthesised in X-Plane's documented format (no X-Plane runs here): `DATA`, one byte, then
36-byte records of an i32 index and eight f32, little-endian. Each datagram holds record 4
(Mach, -, VVI, -, g-load normal, axial, side, -) and record 16 (angular velocities Q, P,
R in rad/s), at 20 Hz: 1 s at rest, a 6 s take-off roll at 0.3 g, the rotation (pitching
up at 0.1 rad/s for 2 s, pulling 1.15 g), then a climbing right turn (rolling right for
1 s, yawing right at 0.05 rad/s, 0.05 g to the side). The axial g-load is positive
backwards and the side one to the right, as Laminar's DataRefs.txt gives the aircraft's
force axes (faxil_plug_acf, fside_plug_acf): speeding up reads a negative axial g-load.
"""
import math
import struct
import sys

def datagram(normal, axial, side, q, p, r):
    out = b"DATA*"
    out += struct.pack("<i8f", 4, 0.2, -999.0, 0.0, -999.0, normal, axial, side, -999.0)
    out += struct.pack("<i8f", 16, q, p, r, -999.0, -999.0, -999.0, -999.0, -999.0)
    return out

def state(t):
    if t < 1.0:
        return (1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if t < 7.0:
        return (1.0, -0.3, 0.0, 0.0, 0.0, 0.0)
    if t < 9.0:
        return (1.15, -0.1, 0.0, 0.1, 0.0, 0.0)
    roll = 0.15 if t < 10.0 else 0.0
    return (1.05, -0.05, 0.05, 0.0, roll, 0.05)

path = sys.argv[1] if len(sys.argv) > 1 else "tests/cli/xplane_takeoff.txt"
with open(path, "w") as f:
    for k in range(0, 241):
        t = k / 20.0
        f.write(f"{t:.2f} {datagram(*state(t)).hex()}\n")
