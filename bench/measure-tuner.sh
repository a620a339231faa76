#!/bin/sh
# Runs hatpic-tuner against the built-in simulator (1 kHz telemetry) under Xvfb and reports
# the CPU it used (utime+stime of all its threads, from /proc/PID/stat) and the repaint rate
# it measured itself (the hatpic.ui.plots debug lines).
#
# usage: [WINDOW=S] [WARMUP=S] bench/measure-tuner.sh BUILD_DIR [SECONDS] [tuner options]
# WINDOW sets the plots' time window (5, 10, 30 or 60 s; default 10) through the settings
# file; WARMUP (default 5 s) passes before the measurement starts.
set -eu
build=$(cd "$1" && pwd)
seconds=${2:-30}
warmup=${WARMUP:-5}
shift
[ $# -gt 0 ] && shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export HOME="$tmp" XDG_CONFIG_HOME="$tmp/config" XDG_RUNTIME_DIR="$tmp"
export QT_LOGGING_RULES="hatpic.ui.plots.debug=true"
mkdir -p "$tmp/config/HATPIC"
printf '[view]\nwindow=%s\n' "${WINDOW:-10}" > "$tmp/config/HATPIC/hatpic-tuner.conf"
xvfb-run -a -s "-screen 0 1400x900x24" sh -c '
    tuner=$1; seconds=$2; log=$3; warmup=$4; shift 4
    "$tuner" --port sim "$@" 2>"$log" &
    pid=$!
    sleep "$warmup" # connect, detect, lay out (and fill the window)
    ticks() { awk "{ print \$14 + \$15 }" /proc/$pid/stat; }
    start=$(ticks)
    sleep "$seconds"
    end=$(ticks)
    hz=$(getconf CLK_TCK)
    kill $pid
    wait $pid 2>/dev/null || true
    awk -v a="$start" -v b="$end" -v hz="$hz" -v s="$seconds" \
        "BEGIN { printf \"CPU: %.1f s in %d s = %.1f %% of one core\n\", (b-a)/hz, s, 100*(b-a)/hz/s }"
' sh "$build/app/hatpic-tuner" "$seconds" "$tmp/log" "$warmup" "$@"
grep -E "repaint rate|latency arrival" "$tmp/log" | tail -n 8 | sed -E "s/^.*(repaint rate|latency arrival)/\1/"
