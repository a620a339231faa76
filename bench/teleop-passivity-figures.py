#!/usr/bin/env python3
# teleop-passivity-figures.py DELAY MODE HAND THETA_EQ CONTACTS SECONDS FILE: passivity.md's
# figures per contact from hatpic-sim --cycle-log (its columns read by name: t_s, theta,
# omega, tau_ext, tau_pc), one table row each. Contact i is the cycles from its push
# (i · (SECONDS + 2) s after the first cycle) to SECONDS later; the last contact ends 0.3 s
# before the last cycle with τ_ext ≠ 0 (the run's teardown: the bridge is stopped first).
# THETA_EQ is robot.md's rest for the hand (hatpicctl teleop-map's theta_eq column).
import csv, math, sys

delay, mode, hand = sys.argv[1], sys.argv[2], sys.argv[3]
th_eq, contacts, seconds = float(sys.argv[4]), int(sys.argv[5]), float(sys.argv[6])
BAND, REST = 0.003, 2.0
# Each row as (t_s, theta, omega, tau, tau_ext, tau_pc): the indices below.
COLUMNS = ("t_s", "theta", "omega", "tau", "tau_ext", "tau_pc")
table = csv.DictReader(open(sys.argv[7]))
rows = [[float(r[c]) for c in COLUMNS] for r in table if None not in r.values()]
lastfb = max((i for i, r in enumerate(rows) if r[4] != 0), default=len(rows) - 1)
rows = rows[:max(2, lastfb - 300)]
t0 = rows[0][0]
for c in range(contacts):
    begin = t0 + c * (seconds + 2.0)
    part = [r for r in rows if begin <= r[0] < begin + seconds]
    if len(part) < 2:
        print(f"| {delay} s | {hand} N·m | {c + 1} | {mode} | no cycles | | | | | |")
        continue
    t = [r[0] for r in part]; th = [r[1] for r in part]; om = [r[2] for r in part]
    te = [r[4] for r in part]; tp = [r[5] for r in part]
    h = t[1] - t[0]; end = t[-1]
    k0 = next((i for i, v in enumerate(te) if v != 0), None)
    if k0 is None:
        print(f"| {delay} s | {hand} N·m | {c + 1} | {mode} | no contact | | | | | |")
        continue
    last = max([i for i in range(k0, len(th)) if abs(th[i] - th_eq) > BAND] or [k0])
    settled = t[last] <= end - REST
    w = [i for i in range(len(t)) if t[i] >= end - REST]
    p2p = max(th[i] for i in w) - min(th[i] for i in w)
    rms = lambda xs: math.sqrt(sum(x * x for x in xs) / max(1, len(xs)))
    k1 = last if settled else len(t) - 1
    ratio = rms(tp[k0:k1 + 1]) / max(1e-12, rms(te[k0:k1 + 1]))
    diss = sum(-tp[i] * om[i] * h for i in range(len(t)))
    damped = sum(1 for i in w if tp[i] != 0) / max(1, len(w))
    mth = sum(th[i] for i in w) / len(w); mte = sum(te[i] for i in w) / len(w)
    settle = f"{t[last] - t[k0]:.2f} s" if settled else "never"
    print(f"| {delay} s | {hand} N·m | {c + 1} | {mode} | {settle} | {p2p * 1000:.1f} mrad | "
          f"{mth:.4f} rad / {mte:.4f} N·m | {ratio:.2f} | {diss * 1000:.1f} mJ | "
          f"{damped * 100:.1f} % |")
