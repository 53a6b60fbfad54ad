#!/usr/bin/env python3
"""The ring compression test with rkpm against Avitzur's upper bound (ring_avitzur.py).

usage: ring_compression.py RUNNER OUT_DIR [--resolution K] [--mu 0,0.05,...] [--no-run]
  runs RUNNER (build/tools/runner/rkpm_run) on cases/ring_compression.json once per Coulomb
  friction mu (--set /contact/friction=mu) into OUT_DIR/mu_<mu>, then prints the table of the
  inner-diameter change against the height reduction (markdown), writes OUT_DIR/ring.dat and
  draws OUT_DIR/ring_compression.png with gnuplot. --no-run reads runs already made.

The runs model the upper half of the ring (a symmetry plane at z = 0), so the full height is
10 mm + 2 x the top die's travel; the inner diameter is the smallest radius of the particles
that started on the inner surface (the barrelled hole's narrowest, at mid-height: what a
calibration measures).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ring_avitzur  # noqa: E402

REDUCTIONS = (10, 20, 30, 40, 50)


def rkpm_curve(run_dir):
    """(reduction %, inner-diameter change % at mid-height, at the die face) per history row."""
    rows = list(csv.DictReader(open(os.path.join(run_dir, "history.csv"))))
    out = []
    for r in rows:
        red = -2.0 * float(r["die_travel_mm"]) / 10.0 * 100.0
        out.append((red, (float(r["inner_radius_min_mm"]) / 7.5 - 1) * 100,
                    (float(r["inner_radius_max_mm"]) / 7.5 - 1) * 100))
    return out


def at(curve, red, col=1):
    for a, b in zip(curve, curve[1:]):
        if a[0] <= red <= b[0]:
            w = (red - a[0]) / (b[0] - a[0]) if b[0] > a[0] else 0.0
            return a[col] + w * (b[col] - a[col])
    return float("nan")


def fitted_m(target, red=50):
    """The friction factor whose Avitzur curve reaches the target change at this reduction."""
    lo, hi = 0.0, 1.0
    f = lambda m: ring_avitzur.curve(m, reductions=(red,), steps=100)[red]
    if target > f(lo) or target < f(hi):
        return float("nan")
    for _ in range(20):
        mid = 0.5 * (lo + hi)
        if f(mid) > target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("runner")
    p.add_argument("out")
    p.add_argument("--resolution", type=int, default=1)
    p.add_argument("--mu", default="0,0.02,0.05,0.08,0.1,0.15,0.2,0.3,0.5")
    p.add_argument("--no-run", action="store_true")
    a = p.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    case = os.path.join(root, "cases", "ring_compression.json")
    mus = [float(x) for x in a.mu.split(",")]
    os.makedirs(a.out, exist_ok=True)
    print("| mu | | " + " | ".join("%d%%" % r for r in REDUCTIONS) + " | kinetic/internal | Avitzur m fitted at 50% |")
    print("|---|---|" + "---|" * len(REDUCTIONS) + "---|---|")
    dat = open(os.path.join(a.out, "ring.dat"), "w")
    for mu in mus:
        d = os.path.join(a.out, "mu_%g" % mu)
        if not a.no_run:
            subprocess.run([a.runner, case, "--set", "/contact/friction=%g" % mu, "--resolution",
                            str(a.resolution), "--out", d, "--threads", "1", "--quiet", "--no-plots"], check=True,
                           stdout=subprocess.DEVNULL)
        c = rkpm_curve(d)
        summary = json.load(open(os.path.join(d, "summary.json")))
        ratio = summary.get("scaled_masses", {}).get("max_kinetic_to_internal", float("nan"))
        m = min(1.0, math.sqrt(3) * mu)
        av = ring_avitzur.curve(m, reductions=REDUCTIONS, steps=100)
        rk = [at(c, r) for r in REDUCTIONS]
        print("| %g | rkpm | " % mu + " | ".join("%+.1f" % x for x in rk)
              + " | %.4f | %.3f |" % (ratio, fitted_m(rk[-1])))
        print("| | Avitzur, m = %.3g | " % m + " | ".join("%+.1f" % av[r] for r in REDUCTIONS) + " | | |")
        dat.write("# mu %g\n" % mu)
        for red, mid, face in c:
            if red <= 50.0 + 1e-9:
                dat.write("%.4f %.4f %.4f\n" % (red, mid, face))
        dat.write("\n\n")
        dat.write("# Avitzur m %g\n" % m)
        avc = ring_avitzur.curve(m, reductions=tuple(range(0, 51, 2)), steps=100)
        for r in sorted(avc):
            dat.write("%d %.4f\n" % (r, avc[r]))
        dat.write("\n\n")
    dat.close()
    png = os.path.join(a.out, "ring_compression.png")
    plots = []
    colours = ["#000000", "#1f77b4", "#2ca02c", "#17becf", "#9467bd", "#ff7f0e", "#d62728",
               "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"]
    for i, mu in enumerate(mus):
        c = colours[i % len(colours)]
        plots.append("'%s' index %d using 1:2 with lines lw 2 lc rgb '%s' title 'rkpm, mu = %g'"
                     % (os.path.join(a.out, "ring.dat"), 2 * i, c, mu))
        plots.append("'%s' index %d using 1:2 with lines dt 2 lc rgb '%s' notitle"
                     % (os.path.join(a.out, "ring.dat"), 2 * i + 1, c))
    script = "\n".join([
        "set terminal pngcairo size 800,600 font ',10'",
        "set output '%s'" % png,
        "set title 'Ring compression 6:3:2: rkpm (solid) and Avitzur upper bound, m = sqrt(3) mu (dashed)'",
        "set xlabel 'height reduction, %'",
        "set ylabel 'change of the inner diameter, %'",
        "set grid",
        "set key outside right",
        "plot " + ", \\\n  ".join(plots),
    ])
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print("figure: %s" % png, file=sys.stderr)


if __name__ == "__main__":
    main()
