#!/usr/bin/python3
"""rkpm_run on several processes (mpiexec -np P rkpm_run ...; tools/runner/ranks.hpp), run by ctest
(tests/tools/runner.cmake) at one thread per process, where runs are reproducible to the bit.

    check_ranks.py same MPIEXEC RKPM_RUN WORK NAME ARGS...
        the case NAME (a built-in case, or a case file) with ARGS on 1, 2 and 3 processes of one
        thread, and on 2 processes of 2 threads: the same history.csv, .pvd (naming .pvtu indexes),
        figure shapes, results, energies, steps and points' extremes, byte for byte, the same
        figures (PNG, block forging on 1 and 2 processes), and the same snapshots: each
        one process's .vtu is, on P processes, a .pvtu index of P pieces that together hold its
        points, arrays and cells bit for bit (pieces.py, read by meshio); summary.json records
        the processes; tools/rkpm view draws the 2 processes' last snapshot with one process's cells.
        With --rereference-* among ARGS (the label NAME_rereferenced), the re-references too; with
        --rebalance-above, at least one repartition on every run of several processes. A case whose
        cracks can grow (summary.json's fragments) must break (history.csv's fragments from 1 to
        more, each over two rows or more), and its fragments, largest fragment's mass and state
        extremes (the failed fraction) are compared too; its snapshots are written whole (.vtu,
        with the crack faces) by rank 0, and compared byte for byte. A run set up
        in parts (summary.json's set_up: a case whose rows reduce, not re-referenced, without cracks;
        rod_on_rod and plate_impact of two bodies too)
        holds on each process about N/P owned particles and fewer than N with its ghosts
        (local_particles); the others say why they are set up whole
    check_ranks.py restart MPIEXEC RKPM_RUN WORK
        block forging (moving tools, friction) checkpointed mid-run on 2 processes, in parts (a
        folder checkpoint_*.rkpmcp of part-0-of-2.rkpmcp and part-1-of-2.rkpmcp, named as one
        process's files), and continued on 1, 2 and 3 gives the uninterrupted run's outputs
        (snapshots in pieces compared as above)
    check_ranks.py errors MPIEXEC RKPM_RUN WORK
        a body that inverts on 2 processes stops both with one line naming the quadrature point
        and the rank, the same point one process names, and summary.json says so; --ranks that
        differs from the processes started, and more processes than particles, are refused in one
        line; no rank is left waiting (every run has a timeout); too little memory for the
        processes on the machine is one warning: set up in parts, the particles a process holds
        with its ghosts (at least those it held, fewer than the whole) and its bytes
        (memory_estimate.hpp's form); set up whole, the whole models they build; a case file's
        "rebalance_above" repartitions unless --rebalance-above overrides it; the edges of a Gmsh
        body after another body reduce (gmsh_edges)

MPIEXEC is the launcher with its flags as one argument ("mpiexec --oversubscribe ..."). The
reference is always the same program on one process: the division must not change a run.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys

import pieces
from checks import check, exit_status, read, run, summary


def launch(mpiexec, processes, rkpm_run, args):
    if processes == 1:
        return run([rkpm_run] + args)
    return run(mpiexec.split() + ["-np", str(processes), rkpm_run] + args)


def snapshot_files(folder):
    return sorted(f for f in os.listdir(folder) if f.endswith((".vtu", ".pvtu")))


def outputs(folder):
    """The other files of a run's folder that must not depend on the processes (not summary.json,
    which records the processes and times)."""
    return sorted(f for f in os.listdir(folder) if f.endswith((".csv", ".pvd")))


def same_snapshot(reference, other, label):
    """One process's snapshot REFERENCE (.vtu) and OTHER: the same file, or, from several processes,
    the same data in pieces (pieces.py)."""
    if other.endswith(".vtu"):
        check(read(reference, "rb") == read(other, "rb"), f"{label}: {os.path.basename(other)} differs from one "
                                                          f"process's")
        return
    for problem in pieces.same_snapshot(reference, other, summary(os.path.dirname(other))["processes"]):
        check(False, f"{label}: {problem}")


def in_pieces(vtu, processes, cracks=False):
    """The files of one process's snapshot X.vtu written by `processes`: X.pvtu and its pieces; X.vtu
    itself from one process, or when cracks can grow (rank 0 writes it whole, with the crack faces)."""
    if processes == 1 or cracks:
        return [vtu]
    stem = vtu[:-len(".vtu")]
    return [stem + ".pvtu"] + [f"{stem}_{r}.vtu" for r in range(processes)]


def same_outputs(reference, other, label):
    a, b = summary(reference), summary(other)
    for key in ["status", "results", "energy", "steps", "dt_min_s", "dt_max_s", "end_time_s", "particles",
                "quadrature_points", "parameters", "rereferences", "rereference_times_s", "fragments",
                "largest_fragment_mass_kg", "points"]:
        check(a.get(key) == b.get(key), f"{label}: summary '{key}' differs: {a.get(key)} vs {b.get(key)}")
    cracks = "fragments" in a  # cracks can grow: the snapshots whole
    files = outputs(reference)
    check(files == outputs(other), f"{label}: other files: {files} vs {outputs(other)}")
    check(any(f.endswith(".pvd") for f in files) and "history.csv" in files, f"{label}: no snapshots or history")
    processes = b["processes"]
    for f in files:
        if f in outputs(other):  # a .pvd names the indexes of the snapshots in pieces
            expected = read(os.path.join(reference, f), "rb")
            if f.endswith(".pvd") and processes > 1 and not cracks:
                expected = expected.replace(b'.vtu"/>', b'.pvtu"/>')
            check(expected == read(os.path.join(other, f), "rb"), f"{label}: {f} differs from one process's")
    snapshots = snapshot_files(reference)
    expected = sorted(x for f in snapshots for x in in_pieces(f, processes, cracks))
    check(snapshot_files(other) == expected, f"{label}: snapshot files {snapshot_files(other)[:8]}..., not "
                                             f"{expected[:8]}...")
    for f in snapshots:
        other_file = os.path.join(other, in_pieces(f, processes, cracks)[0])
        if os.path.exists(other_file):
            same_snapshot(os.path.join(reference, f), other_file, label)


# The cases the runner sets up whole on several processes, and why (tools/runner/part_setup.hpp).
SET_UP_WHOLE = {"taylor_bar_rereferenced": "re-reference", "brittle_bar": "cracks can grow"}


def local_particles(folder, processes, label, whole_because=None):
    """summary.json's set-up and each process's particles on a run of several processes: set up in parts,
    about N/P owned particles each (coordinate bisection: within 10%, and together N) and fewer than N with
    its ghosts; set up whole, the reason."""
    s = summary(folder)
    n, local = s["particles"], s.get("local_particles", [])
    check(len(local) == processes and sum(r["owned"] for r in local) == n,
          f"{label}: local_particles {local} do not divide the {n} particles")
    if whole_because:
        check(s.get("set_up") == "whole" and whole_because in s.get("whole_model_because", ""),
              f"{label}: set up {s.get('set_up')} ({s.get('whole_model_because')}), not whole for {whole_because}")
        return
    check(s.get("set_up") == "in parts", f"{label}: set up {s.get('set_up')} ({s.get('whole_model_because')}), "
                                         f"not in parts")
    for r in local:
        check(abs(r["owned"] - n / processes) <= 0.1 * n / processes and r["owned"] + r["ghosts"] < n,
              f"{label}: a process holds {r['owned']} owned and {r['ghosts']} ghost particles of {n}: not about "
              f"N/P plus ghosts")


def same(mpiexec, rkpm_run, work, name, args):
    label = os.path.splitext(os.path.basename(name))[0]
    if any(a.startswith("--rereference") for a in args):
        label += "_rereferenced"
    folders = {}
    # (processes, threads per process): one thread each, and 2 processes of 2 threads.
    # The figures (PNG) on 1 and 2 processes of one thread, for the block forging (set up in parts;
    # its four shapes and the end-state figure from gathered positions): gnuplot costs seconds a run.
    for p, threads in ((1, 1), (2, 1), (3, 1), (2, 2)):
        out = os.path.join(work, f"{label}-{p}x{threads}")
        shutil.rmtree(out, ignore_errors=True)
        plots = [] if label == "block_forging" and p < 3 and threads == 1 else ["--no-plots"]
        r = launch(mpiexec, p, rkpm_run, [name] + args + plots + ["--quiet", "--threads", str(threads), "--out", out])
        check(r.returncode == 0, f"{label} on {p} processes failed: {r.stdout[-2000:]} {r.stderr[-2000:]}")
        if r.returncode != 0:
            return
        check(summary(out).get("processes") == p, f"{label}: summary.json records {summary(out).get('processes')} "
                                                  f"processes, not {p}")
        folders[p, threads] = out
    for p, threads in ((2, 1), (3, 1), (2, 2)):
        local_particles(folders[p, threads], p, f"{label} on {p} processes", SET_UP_WHOLE.get(label))
    if "--rebalance-above" in args:  # what the bound is for: the particles partitioned again
        for p, threads in ((2, 1), (3, 1), (2, 2)):
            n = summary(folders[p, threads]).get("repartitions", 0)
            check(n > 0, f"{label} on {p} processes: no repartition (summary.json: {n})")
    rows = read(os.path.join(folders[1, 1], "history.csv")).count("\n") - 1
    check(rows >= 10, f"{label}: only {rows} history rows: too short a run to compare")
    if "fragments" in summary(folders[1, 1]):  # cracks can grow: what the run is for, a body broken
        with open(os.path.join(folders[1, 1], "history.csv")) as f:
            pieces = [float(row["fragments"]) for row in csv.DictReader(f)]
        check(pieces[0] == 1 and summary(folders[1, 1])["fragments"] > 1 and pieces.count(1) >= 2 and
              pieces.count(pieces[-1]) >= 2, f"{label}: the fragments over time {pieces}: the rows do not see one "
                                             f"piece, then several")
    for p, threads in ((2, 1), (3, 1), (2, 2)):
        same_outputs(folders[1, 1], folders[p, threads], f"{label} on {p} processes of {threads} thread(s)")
    figures = sorted(f for f in os.listdir(folders[1, 1]) if f.endswith(".png"))
    check(figures == sorted(f for f in os.listdir(folders[2, 1]) if f.endswith(".png")),
          f"{label}: other figures on 2 processes than {figures}")
    for f in figures:
        check(read(os.path.join(folders[1, 1], f), "rb") == read(os.path.join(folders[2, 1], f), "rb"),
              f"{label}: {f} on 2 processes differs from one process's")
    view(folders[1, 1], folders[2, 1], label)
    print(f"ok  {label}: {summary(folders[1, 1])['steps']} steps, {rows} history rows, the same files on 1, 2 and 3 "
          f"processes of one thread and 2 of two threads; tools/rkpm view draws the pieces")


CASES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases")
VIEW = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "tools", "view", "rkpm_view.py")


def view(one, two, label):
    """tools/rkpm view (tools/view/rkpm_view.py) on the 2-process run: it reads the last snapshot's
    pieces as one mesh whose cells, drawn at their points, are one process's, and writes a PNG."""
    import numpy as np
    sys.path.insert(0, os.path.dirname(VIEW))
    import rkpm_view

    def drawn(folder):
        t, path = rkpm_view.snapshots(folder)[-1]
        mesh = rkpm_view.read_snapshot(path)
        return sorted((b.type, mesh.points[row].tobytes()) for b in mesh.cells for row in np.asarray(b.data))

    check(drawn(one) == drawn(two), f"{label}: the view of the pieces draws other cells than one process's")
    out = os.path.join(two, "view.png")
    r = run(["/usr/bin/python3", VIEW, two, "--field", "stress", "--out", out])
    check(r.returncode == 0 and read(out, "rb")[:4] == b"\x89PNG", f"{label}: tools/rkpm view on the pieces: "
                                                                    f"{r.stdout} {r.stderr}")


def checkpoints(folder):
    return sorted(f for f in os.listdir(folder) if f.startswith("checkpoint_") and f.endswith(".rkpmcp"))


def restart(mpiexec, rkpm_run, work):
    case, end = "block_forging", 3e-4
    base = [case, "--set", "particles_per_side=9", "--set", "friction=0.3", "--end-time", repr(end), "--no-plots",
            "--quiet", "--threads", "1"]
    full1, full2 = os.path.join(work, "restart-full-1"), os.path.join(work, "restart-full-2")
    for d in (full1, full2):
        shutil.rmtree(d, ignore_errors=True)
    for p, out in ((1, full1), (2, full2)):
        r = launch(mpiexec, p, rkpm_run, base + ["--checkpoint-interval", repr(end / 2), "--out", out])
        check(r.returncode == 0, f"the run on {p} processes failed: {r.stderr[-2000:]}")
        if r.returncode != 0:
            return
    ck = checkpoints(full2)
    check(len(ck) == 2 and ck == checkpoints(full1), f"checkpoints {ck} on 2 processes, {checkpoints(full1)} on 1")
    for f in ck:
        folder = os.path.join(full2, f)
        parts = sorted(os.listdir(folder)) if os.path.isdir(folder) else None
        check(parts == ["part-0-of-2.rkpmcp", "part-1-of-2.rkpmcp"], f"{f} on 2 processes is not a folder of 2 "
                                                                       f"parts: {parts}")
    same_outputs(full1, full2, "the run with checkpoints on 2 processes")
    for p in (1, 2, 3):
        cont = os.path.join(work, f"restart-cont-{p}")
        shutil.rmtree(cont, ignore_errors=True)
        r = launch(mpiexec, p, rkpm_run, [case, "--restart", os.path.join(full2, ck[0]), "--out", cont, "--no-plots",
                                          "--quiet", "--threads", "1"])
        check(r.returncode == 0, f"the restart on {p} processes failed: {r.stderr[-2000:]}")
        if r.returncode != 0:
            continue
        label = f"2 processes' checkpoint {ck[0]} continued on {p}"
        a, b = summary(full1), summary(cont)
        for key in ["results", "energy", "steps", "end_time_s"]:
            check(a[key] == b[key], f"{label}: summary '{key}' differs: {a[key]} vs {b[key]}")
        check(read(os.path.join(full1, "history.csv")) == read(os.path.join(cont, "history.csv")),
              f"{label}: history.csv differs from the uninterrupted run's")
        last = snapshot_files(full1)[-1]
        same_snapshot(os.path.join(full1, last), os.path.join(cont, in_pieces(last, p)[0]),
                      f"{label}: the last snapshot")
        print(f"ok  {label}: the uninterrupted run's results, history and last snapshot")


def errors(mpiexec, rkpm_run, work):
    bar = ["taylor_bar", "--set", "radial_particles=6", "--set", "axial_particles=16", "--end-time", "2e-6",
           "--no-plots", "--quiet", "--threads", "1"]
    # An impact at 30 km/s inverts the bar in its first step.
    fast = bar + ["--set", "velocity_m_s=3e4"]
    one, two = os.path.join(work, "inverted-1"), os.path.join(work, "inverted-2")
    r1 = launch(mpiexec, 1, rkpm_run, fast + ["--out", one])
    r2 = launch(mpiexec, 2, rkpm_run, fast + ["--out", two])
    check(r1.returncode != 0 and r2.returncode != 0, "the inverted bar did not fail")
    lines = [l for l in r2.stderr.splitlines() if l.startswith("rkpm_run")]
    check(len(lines) == 1, f"2 processes said {len(lines)} rkpm_run lines, not one: {lines}")
    # The same message as one process's, but for the rank and the run's folder.
    expected = r1.stderr.strip().splitlines()[0].replace("rkpm_run: ", "").split(" (what was written")[0]
    check(len(lines) == 1 and lines[0].startswith("rkpm_run: rank ") and " of 2: " in lines[0] and
          lines[0].split(" of 2: ", 1)[1].split(" (what was written")[0] == expected,
          f"the line on 2 processes {lines} is not one process's '{expected}' with the rank")
    check("det F" in expected and "quadrature point" in expected, f"the failure does not name the point: {expected}")
    s = summary(two)
    check(s["status"] == "failed" and "rank " in s.get("error", ""), f"summary.json: {s['status']} {s.get('error')}")
    print(f"ok  an inverted body on 2 processes: {lines[0][:90]}...")

    r = launch(mpiexec, 2, rkpm_run, bar + ["--ranks", "3", "--out", os.path.join(work, "ranks")])
    check(r.returncode != 0 and "--ranks 3: this is 2 processes" in r.stderr, f"--ranks 3 on 2: {r.stderr[-500:]}")
    r = launch(mpiexec, 1, rkpm_run, bar + ["--ranks", "2", "--out", os.path.join(work, "ranks")])
    check(r.returncode != 0 and "start it with mpiexec -np 2" in r.stderr, f"--ranks 2 alone: {r.stderr[-500:]}")
    tiny = ["taylor_bar", "--set", "radial_particles=2", "--set", "axial_particles=2", "--end-time", "1e-7",
            "--no-plots", "--quiet", "--threads", "1", "--out", os.path.join(work, "tiny")]
    r = launch(mpiexec, 5, rkpm_run, tiny)
    check(r.returncode != 0 and "5 processes for 4 particles" in r.stderr, f"5 processes for 4 particles: "
                                                                           f"{r.stderr[-500:]}")
    print("ok  --ranks other than the processes started, and more processes than particles, are refused")

    # Too little memory for the processes on this machine: one warning for the machine, not one per
    # process (the memory forced small). Set up in parts (the bar at resolution 2, 4,141
    # particles): the particles a process holds with its ghosts, at least what each held and fewer
    # than the whole, and the bytes of memory_estimate.hpp's form for them and the layout.
    memory = os.path.join(work, "memory")
    r = subprocess.run(mpiexec.split() + ["-np", "2", rkpm_run, "taylor_bar", "--resolution", "2", "--end-time", "1e-7",
                                          "--no-plots", "--quiet", "--threads", "1", "--out", memory],
                       capture_output=True, text=True, timeout=300,
                       env=dict(os.environ, RKPM_AVAILABLE_MEMORY_BYTES="1e4"))
    warnings = [l for l in r.stderr.splitlines() if "warning" in l]
    check(r.returncode == 0 and len(warnings) == 1, f"the memory warning on 2 processes: {warnings} {r.stderr[-500:]}")
    if r.returncode == 0 and len(warnings) == 1:
        s = summary(memory)
        n, points = s["particles"], s["quadrature_points"]
        held = max(p["owned"] + p["ghosts"] for p in s["local_particles"])
        found = re.search(r"about (\d+) particles with their ghosts and ([\d.]+) MB each", warnings[0])
        estimated, mb = (int(found[1]), float(found[2])) if found else (0, 0.0)
        expected_mb = ((0.6e3 + 0.55e3 * points / n) * estimated + 200.0 * n) / 1e6
        check(s["set_up"] == "in parts" and f"each set up their part of {n} particles in parts" in warnings[0] and
              held <= estimated < n and abs(mb - expected_mb) <= 0.5,
              f"the memory warning in parts: {warnings[0]} (held {held} of {n}; {expected_mb:.1f} MB expected)")
        print(f"ok  one memory warning for the machine: {estimated} particles estimated per process, {held} held, "
              f"of {n}: {warnings[0][:100]}...")
    # Set up whole (re-referenced): the whole models the processes build and rank 0's whole solver.
    r = subprocess.run(mpiexec.split() + ["-np", "2", rkpm_run, "taylor_bar", "--rereference-every", "10",
                                          "--end-time", "1e-7", "--no-plots", "--quiet", "--threads", "1",
                                          "--out", memory + "-whole"],
                       capture_output=True, text=True, timeout=300,
                       env=dict(os.environ, RKPM_AVAILABLE_MEMORY_BYTES="1e4"))
    warnings = [l for l in r.stderr.splitlines() if "warning" in l]
    check(r.returncode == 0 and len(warnings) == 1 and "each build the whole model of" in warnings[0] and
          "rank 0 keeps a whole solver" in warnings[0] and "for 3 copies" in warnings[0],
          f"the memory warning on 2 processes set up whole: {warnings} {r.stderr[-500:]}")

    # A case file's "rebalance_above" is the run's bound unless --rebalance-above is given: a bound
    # just above 1 repartitions at the re-references, the command line's 1e9 never.
    case = json.loads(read(os.path.join(CASES, "taylor_bar_johnson_cook.json")))
    case["bodies"][0]["shape"]["rectangle"]["particles"] = [6, 12]
    case["end_time_s"] = 3e-6
    case["output"] = {"snapshots": 0, "history_rows": 4}
    case["rereference"] = {"max_stretch": 1.02, "every_steps": 10, "rebalance_above": 1.000001}
    file = os.path.join(work, "rebalanced_bar.json")
    with open(file, "w") as f:
        json.dump(case, f)
    counts = []
    for extra in ([], ["--rebalance-above", "1e9"]):
        out = os.path.join(work, "rebalanced" + "".join(extra))
        r = launch(mpiexec, 2, rkpm_run, [file, "--no-plots", "--quiet", "--threads", "1", "--out", out] + extra)
        check(r.returncode == 0, f"the rebalanced bar with {extra}: {r.stderr[-500:]}")
        counts.append(summary(out).get("repartitions", 0) if r.returncode == 0 else None)
    passed = bool(counts[0]) and counts[1] == 0
    check(passed, f"the file's rebalance_above: {counts[0]} repartitions (expected some), with --rebalance-above "
                  f"1e9: {counts[1]} (expected none)")
    if passed:
        print(f"ok  a case file's rebalance_above: {counts[0]} repartitions on 2 processes, none with --rebalance-above "
              "1e9")
    gmsh_edges(mpiexec, rkpm_run, work)


def gmsh_edges(mpiexec, rkpm_run, work):
    """An edge of a Gmsh body that is not the first body (its node i is the particle after the
    bodies before it, model_bodies::first_particle) is measured by reduction, as every other
    history: on 1 and 2 processes the same history.csv byte for byte, and its first row the
    geometry's (projectile.geo: the nose arc reaches x = 5 mm, the back is at y = 25 mm)."""
    j2 = {"law": "j2", "hardening": "linear", "youngs_modulus_Pa": 117e9, "poisson_ratio": 0.35,
          "density_kg_m3": 8930, "yield_stress_Pa": 400e6, "hardening_modulus_Pa": 100e6}
    case = {
        "name": "block_and_projectile", "geometry": "plane_strain",
        "method": {"kernel": "cubic", "correction": "linear", "quadrature": "q2", "contact": "paper"},
        "end_time_s": 2e-7,
        "bodies": [
            {"name": "block", "material": j2,
             "shape": {"rectangle": {"lower_left_m": [10e-3, 0], "upper_right_m": [14e-3, 4e-3], "particles": [5, 5]}}},
            {"name": "projectile", "material": j2, "initial_velocity_m_s": [0, -150],
             "shape": {"mesh": {"file": os.path.join(CASES, "projectile", "projectile.geo")}}}],
        "output": {"snapshots": 0, "history_rows": 2},
        "histories": [
            {"name": "nose_max_x_mm", "extent": {"body": "projectile", "of": "max_x", "on_edge": "nose", "scale": 1e3}},
            {"name": "back_min_y_mm", "extent": {"body": "projectile", "of": "min_y", "on_edge": "back", "scale": 1e3}}]}
    file = os.path.join(work, "block_and_projectile.json")
    with open(file, "w") as f:
        json.dump(case, f)
    outs = []
    for p in (1, 2):
        out = os.path.join(work, f"block_and_projectile-{p}")
        shutil.rmtree(out, ignore_errors=True)
        r = launch(mpiexec, p, rkpm_run, [file, "--no-plots", "--quiet", "--threads", "1", "--out", out])
        check(r.returncode == 0, f"the block and the projectile on {p} processes: {r.stderr[-500:]}")
        if r.returncode != 0:
            return
        outs.append(out)
    because = summary(outs[1]).get("whole_model_because", "")
    reduced = "rows" not in because
    check(reduced, f"the Gmsh body's edges did not reduce: set up whole because {because!r}")
    histories = [read(os.path.join(o, "history.csv")) for o in outs]
    same_rows = histories[0] == histories[1]
    check(same_rows, "the Gmsh body's edges: history.csv differs between 1 and 2 processes")
    first = next(csv.DictReader(histories[0].splitlines()))
    nose, back = float(first["nose_max_x_mm"]), float(first["back_min_y_mm"])
    at_start = abs(nose - 5.0) < 1e-9 and abs(back - 25.0) < 1e-9
    check(at_start, f"the projectile's edges at the start: nose reaches x = {nose} mm (5), back at y = {back} mm (25)")
    if reduced and same_rows and at_start:
        print(f"ok  the edges of a Gmsh body after another body, reduced: nose {nose} mm, back {back} mm, the same "
              "rows on 1 and 2 processes")


def main():
    mode, mpiexec, rkpm_run, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    if mode == "same":
        same(mpiexec, rkpm_run, work, sys.argv[5], sys.argv[6:])
    elif mode == "restart":
        restart(mpiexec, rkpm_run, work)
    elif mode == "errors":
        errors(mpiexec, rkpm_run, work)
    else:
        sys.exit(f"unknown mode {mode}")
    sys.exit(exit_status())


if __name__ == "__main__":
    main()
