#!/usr/bin/env python3
import csv, math, sys
# analyse.py DELAY MODE FILE: passivity.md's figures from hatpic-sim --cycle-log, the run's
# teardown (from 0.3 s before the last cycle with τ_ext ≠ 0) cut off.
TH_EQ = 0.0625
rows = [[float(x) for x in r] for r in list(csv.reader(open(sys.argv[3])))[1:] if len(r) == 8]
lastfb = max((i for i, r in enumerate(rows) if r[4] != 0), default=len(rows) - 1)
rows = rows[:max(2, lastfb - 300)]
t = [r[0] for r in rows]; th = [r[1] for r in rows]; om = [r[2] for r in rows]
te = [r[4] for r in rows]; tp = [r[5] for r in rows]
h = t[1] - t[0]; end = t[-1]
k0 = next((i for i, v in enumerate(te) if v != 0), None)
if k0 is None:
    print(f"| {sys.argv[1]} s | {sys.argv[2]} | no contact | | | | | |"); sys.exit()
last = max([i for i in range(k0, len(th)) if abs(th[i] - TH_EQ) > 0.003] or [k0])
settled = t[last] <= end - 2.0
w = [i for i in range(len(t)) if t[i] >= end - 2.0]
p2p = max(th[i] for i in w) - min(th[i] for i in w)
rms = lambda xs: math.sqrt(sum(x * x for x in xs) / max(1, len(xs)))
k1 = last if settled else len(t) - 1
ratio = rms(tp[k0:k1 + 1]) / max(1e-12, rms(te[k0:k1 + 1]))
diss = sum(-tp[i] * om[i] * h for i in range(len(t)))
rest = range(k1 + 1, len(t)) if settled else w
idle = sum(1 for i in rest if tp[i] == 0) / max(1, len(rest))
mth = sum(th[i] for i in w) / len(w); mte = sum(te[i] for i in w) / len(w)
settle = f"{t[last] - t[k0]:.2f} s" if settled else "never"
print(f"| {sys.argv[1]} s | {sys.argv[2]} | {settle} | {p2p * 1000:.1f} mrad | {mth:.4f} rad / {mte:.4f} N·m | {ratio:.2f} | {diss * 1000:.1f} mJ | {idle * 100:.1f} % |")
