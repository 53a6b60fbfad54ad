#!/usr/bin/env python3
"""Tutorial 12: a parameter study from Python. The Taylor bar (cases/taylor_bar.hpp: copper,
R0 = 3.2 mm, L0 = 32.4 mm, on a rigid wall) at five impact speeds in one process, with an
observer that follows the impact face's radius during each run; the final length against speed
goes to speed_sweep.csv and speed_sweep.png.

    tools/rkpm python tutorials/12_python/speed_sweep.py [OUT_DIR] [--quick]

--quick runs a coarse bar (11 x 21 particles) for 20 us instead of the paper's 21 x 51 for
80 us, so the whole study takes seconds. The plot is drawn by matplotlib when python3-matplotlib
is installed, by gnuplot otherwise.
"""
import os
import shutil
import subprocess
import sys

import numpy as np
import rkpm

args = [a for a in sys.argv[1:] if not a.startswith("--")]
quick = "--quick" in sys.argv
out = args[0] if args else os.path.join("results", "tutorial_12")
os.makedirs(out, exist_ok=True)

speeds = [100.0, 150.0, 200.0, 227.0, 250.0]  # m/s; 227 m/s is the paper's
settings = {"radial_particles": 11, "axial_particles": 21} if quick else {}
end_time = 20e-6 if quick else None

rows = []
for v in speeds:
    radius_history = []

    def follow(state):
        # The impact face: the particles whose reference position (position - displacement)
        # is on y = 0; its radius is their largest x.
        bottom = state.positions[:, 1] - state.displacement[:, 1] < 1e-9
        radius_history.append((state.time_s, float(np.max(state.positions[bottom, 0]))))
        return True  # keep going (False would stop the run here)

    result = rkpm.run("taylor_bar", set={**settings, "velocity_m_s": v}, end_time=end_time,
                      out=os.path.join(out, f"v{v:g}"), plots=False, observe=follow, every=50)
    r = result.summary["results"]
    rows.append((v, r["height_mm"], r["radius_mm"], r["max_equivalent_plastic_strain"]))
    print(f"v = {v:5.0f} m/s: final length {r['height_mm']:.3f} mm, impact-face radius {r['radius_mm']:.3f} mm, "
          f"max eps_p {r['max_equivalent_plastic_strain']:.3f}, {result.summary['steps']} steps "
          f"(observer: radius {radius_history[0][1] * 1e3:.2f} -> {radius_history[-1][1] * 1e3:.2f} mm)")

csv_path = os.path.join(out, "speed_sweep.csv")
with open(csv_path, "w") as f:
    f.write("velocity_m_s,final_length_mm,impact_face_radius_mm,max_equivalent_plastic_strain\n")
    for row in rows:
        f.write(",".join(f"{x:.10g}" for x in row) + "\n")

png = os.path.join(out, "speed_sweep.png")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot([r[0] for r in rows], [r[1] for r in rows], "o-")
    ax.set_xlabel("impact speed (m/s)")
    ax.set_ylabel("final length (mm)")
    ax.set_title("Taylor bar: final length against impact speed")
    fig.savefig(png, dpi=120, bbox_inches="tight")
except ImportError:
    if shutil.which("gnuplot"):
        script = (f"set terminal pngcairo size 720,480; set output '{png}'; set datafile separator ',';"
                  "set xlabel 'impact speed (m/s)'; set ylabel 'final length (mm)'; set key off;"
                  "set title 'Taylor bar: final length against impact speed';"
                  f"plot '{csv_path}' skip 1 using 1:2 with linespoints pt 7")
        subprocess.run(["gnuplot", "-e", script], check=True)
    else:
        png = None
print(f"wrote {csv_path}" + (f" and {png}" if png else " (no matplotlib or gnuplot for the plot)"))
