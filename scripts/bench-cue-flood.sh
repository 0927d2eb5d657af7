#!/usr/bin/env bash
# The sender's timing with a live cue (`stewart link --cue`) at 1 kHz, first with a
# simulator's pace of input (200 samples a second), then while the cue port is flooded
# (as many datagrams as one Python process can send, valid samples and junk). The
# period error (mean, p99, max) must not follow the input's rate.
#   SECONDS_PER_RUN=5 bash scripts/bench-cue-flood.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q -p stewart_app
S=target/release/stewart
SECS=${SECONDS_PER_RUN:-5}
PORT=${PORT:-47123}
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
send() { # $1: pause between datagrams (0: flood)
  python3 - "$PORT" "$1" "$SECS" <<'PY'
import socket, sys, time
port, pause, secs = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]) + 1.0
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
start = time.time(); k = 0; sent = 0
while time.time() - start < secs:
    t = time.time() - start
    data = (f"{t},-3,0.5,0,0,0,10" if k % 4 else "junk " * 200).encode()
    try:
        s.sendto(data, ("127.0.0.1", port)); sent += 1
    except OSError:
        pass
    k += 1
    if pause:
        time.sleep(pause)
print(f"# sent {sent} datagrams ({sent / secs:.0f} a second)", file=sys.stderr)
PY
}
for pause in 0.005 0; do
  if [ "$pause" = 0 ]; then echo "# flooded"; else echo "# 200 datagrams a second"; fi
  send "$pause" &
  sender=$!
  $S link --preset seed --cue "udp:127.0.0.1:$PORT" --dry-run --out /dev/null \
    --rate 1000 --duration "$SECS" 2>&1 | grep -E "^link: [0-9]+ frames|cue:"
  wait $sender
done
