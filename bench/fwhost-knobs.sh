#!/usr/bin/env bash
# The device core with N knobs on Linux at 1 kHz: hatpic-servo-sim --servos N (N emulated
# STS3032 on one pty), hatpic-fw-host --servos N driving them (one controller per servo, every
# knob a READ and a WRITE per cycle), and hatpicctl streaming every cycle's TELEMETRY (all N
# knobs in each frame) for SECONDS. Prints hatpic-fw-host's "total" timing line and hatpicctl's
# link statistics: frames received and missing by seq, decoder drops.
#
# Usage: bench/fwhost-knobs.sh [BUILD_DIR] [KNOBS] [SECONDS]    (defaults: build 4 30)
# With SERVO_CHRT="chrt -f 40" the servo emulator runs at real-time priority (docs/
# performance.md explains why that matters on a loaded machine).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build}
knobs=${2:-4}
seconds=${3:-30}
cmake --build "$build" -j2 --target hatpic-servo-sim hatpic-fw-host hatpicctl >&2

work=$(mktemp -d)
servo_pid=
host_pid=
cleanup() {
  [[ -n $host_pid ]] && kill -TERM "$host_pid" 2>/dev/null || true
  [[ -n $servo_pid ]] && kill -TERM "$servo_pid" 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

hands=(--hand const:0.02 --hand-2 const:-0.02 --hand-3 sine:0.02:0.5 --hand-4 const:0.01)
${SERVO_CHRT:-} "$build/app/hatpic-servo-sim" --servos "$knobs" "${hands[@]:0:$((2 * knobs))}" \
  --link "$work/servo" >/dev/null 2>"$work/servo.log" &
servo_pid=$!
for _ in $(seq 50); do [[ -e $work/servo ]] && break; sleep 0.1; done
"$build/app/hatpic-fw-host" --servo "$work/servo" --servos "$knobs" --link "$work/fwhost" \
  >/dev/null 2>"$work/fwhost.log" &
host_pid=$!
for _ in $(seq 50); do [[ -e $work/fwhost ]] && break; sleep 0.1; done

echo "== $knobs knobs, ${seconds} s, 1 kHz stream; load $(cut -d' ' -f1-3 /proc/loadavg)"
"$build/app/hatpicctl" stream --port "$work/fwhost" --rate 1000 --duration "$seconds" \
  2>&1 >/dev/null | grep -E "samples|frames|decoder drops" || true
kill -TERM "$host_pid"
wait "$host_pid" || true
host_pid=
grep -E "hatpic-fw-host: (total|control thread|.*servos)" "$work/fwhost.log"
