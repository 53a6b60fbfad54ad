#!/usr/bin/python3
"""Checks of the command-line runner rkpm_run (tools/runner), run by ctest (tests/tools/runner.cmake).

    check_runner.py bad-options RKPM_RUN WORK_DIR  bad options: non-zero exit, one-line error naming the fix, no output
    check_runner.py help RKPM_RUN                  `CASE --help` lists every case's parameters
    check_runner.py run RKPM_RUN OUT_DIR           a short Taylor bar run (the fixture of the next two)
    check_runner.py outputs OUT_DIR                summary.json keys and values, history.csv, .pvd, PNGs
    check_runner.py vtk OUT_DIR                    the VTK series read back with meshio (independent reader)
    check_runner.py view VIEW_SCRIPT OUT_DIR      tools/rkpm view (tools/view/rkpm_view.py) on that run's folder
    check_runner.py rod-on-rod RKPM_RUN WORK_DIR   rod_on_rod with every contact policy, rule, kernel, correction

The numbers are checked against physics and the run's own request (particle count 21 x 21, end time,
initial velocity 227 m/s, reference + displacement = current points), never against stored output.
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

RADIAL, AXIAL = 21, 21  # the run below: --set axial_particles=21, radial_particles default 21
END_TIME = 2e-6
VELOCITY = 227.0
RADIUS_MM, HEIGHT_MM = 3.2, 32.4

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message)


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120, **kw)


def bad_options(rkpm_run, work):
    out = os.path.join(work, "bad")
    shutil.rmtree(out, ignore_errors=True)
    # (arguments, words the error must contain)
    cases = [
        ["nosuch_case"],
        ["--quiet"],
        ["taylor_bar", "--frobnicate"],
        ["taylor_bar", "--quadrature", "q7"],
        ["taylor_bar", "--kernel", "gaussian"],
        ["taylor_bar", "--set", "bogus=1"],
        ["taylor_bar", "--set", "velocity_m_s=abc"],
        ["taylor_bar", "--set", "velocity_m_s=1e400"],
        ["taylor_bar", "--set", "velocity_m_s"],
        ["taylor_bar", "--resolution", "0"],
        ["taylor_bar", "--resolution", "two"],
        ["taylor_bar", "--end-time", "-1"],
        ["taylor_bar", "--end-time"],
        ["taylor_bar", "--threads", "2x"],
        ["taylor_bar", "--contact", "sticky"],
        ["taylor_bar", "--vtu-compression", "gzip"],
        ["taylor_bar", "--set", "radial_particles=1"],
        ["wheel_forging", "--set", "tool_vertex_slaves=0.5"],
        ["paper", "--resolution", "2x"],
        ["paper", "--threads", "0"],
        ["paper", "--cases", "taylor_bar,nosuch_case"],
        ["block_forging", "--set", "end_time_s=1"],  # the tools would meet: the case rejects it
    ]
    # Counts are whole numbers: a fraction is an error that names the parameter and the fix.
    named = {
        ("taylor_bar", "--set", "radial_particles=2.5"): ["radial_particles", "whole number", "radial_particles=3"],
        ("block_forging", "--set", "particles_per_side=20.7"): ["particles_per_side", "whole number",
                                                                "particles_per_side=21"],
        ("wheel_forging", "--set", "axial_particles=1e3"): ["axial_particles", "whole number"],
    }
    cases += [list(k) for k in named]
    for args in cases:
        r = run([rkpm_run] + args + ["--out", out, "--no-plots", "--quiet"])
        err = r.stderr.rstrip("\n")
        label = " ".join(args)
        for word in named.get(tuple(args), []):
            check(word in err, f"'{label}': the error does not say {word!r}: {err!r}")
        check(r.returncode != 0, f"'{label}': exit status {r.returncode}, expected non-zero")
        check(err != "" and "\n" not in err, f"'{label}': expected a one-line error, got {r.stderr!r}")
        check(err.startswith("rkpm_run: "), f"'{label}': error does not start with 'rkpm_run: ': {err!r}")
        check(r.stdout == "", f"'{label}': unexpected output {r.stdout!r}")
        print(f"ok  {label!r:50} -> {err}")
    # Option errors are found before any simulation starts: nothing but the failed case's
    # summary (block_forging, whose set-up failed) may be written.
    summary = os.path.join(out, "summary.json")
    if os.path.exists(summary):
        with open(summary) as f:
            s = strict_json(f)
        check(s.get("status") == "failed" and "error" in s, f"summary of a failed set-up: {s}")
        check(s.get("case") == "block_forging", f"only the set-up failure may write a summary, got {s.get('case')}")


def step_budget(rkpm_run, work):
    """A run that would need more steps than --max-steps is refused before it starts, in a few
    seconds, with the estimate and the likely cause; its summary records the failure."""
    for args, words in [
        (["taylor_bar", "--set", "youngs_modulus_Pa=1e30", "--end-time", "1e-6"], ["steps", "max_steps", "modulus"]),
        (["taylor_bar", "--max-steps", "100"], ["steps", "max_steps = 100"]),
    ]:
        out = os.path.join(work, "budget")
        shutil.rmtree(out, ignore_errors=True)
        r = run([rkpm_run] + args + ["--out", out, "--no-plots", "--quiet"])
        err = r.stderr.rstrip("\n")
        label = " ".join(args)
        check(r.returncode != 0, f"'{label}': exit status {r.returncode}, expected non-zero")
        check(err.count("\n") == 0 and err.startswith("rkpm_run: "), f"'{label}': expected a one-line error: {err!r}")
        for word in words:
            check(word in err, f"'{label}': the error does not say {word!r}: {err!r}")
        with open(os.path.join(out, "summary.json")) as f:
            s = strict_json(f)
        check(s.get("status") == "failed" and "max_steps" in s.get("error", ""), f"'{label}': summary {s}")
        print(f"ok  {label!r:50} -> {err}")
    r = run([rkpm_run, "taylor_bar", "--max-steps", "0"])
    check(r.returncode != 0 and "max-steps" in r.stderr, f"--max-steps 0 accepted: {r.stderr!r}")
    # A problem larger than the memory available is warned about before it is built (the
    # available memory forced small; 21 x 51 particles at about 1.8 KB each need 2 MB).
    out = os.path.join(work, "budget")
    r = subprocess.run([rkpm_run, "taylor_bar", "--end-time", "1e-7", "--out", out, "--no-plots", "--quiet"],
                       capture_output=True, text=True, timeout=120, env=dict(os.environ, RKPM_AVAILABLE_MEMORY_BYTES="1e6"))
    check(r.returncode == 0 and "warning: 1071 particles need about 2 MB" in r.stderr and "only 1 MB" in r.stderr,
          f"no memory warning: {r.stderr!r}")
    r = run([rkpm_run, "taylor_bar", "--end-time", "1e-7", "--out", out, "--no-plots", "--quiet"])
    check("warning" not in r.stderr, f"a memory warning on a small run: {r.stderr!r}")
    mass_scaling(rkpm_run, work)
    hot_forging(rkpm_run, work)
    ring_compression(rkpm_run, work)


def hot_forging(rkpm_run, work):
    """cases/hot_forging.json for its first tenth (5% reduction): the heat ledger balances, the
    dies chill the billet (heat flows to them, the coldest particle below the start), the plastic
    work heats it, history.csv has the heat columns, final_temperature.png is drawn."""
    case = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases", "hot_forging.json")
    out = os.path.join(work, "hot_forging")
    shutil.rmtree(out, ignore_errors=True)
    r = run([rkpm_run, case, "--end-time", "0.05", "--out", out, "--quiet"])
    check(r.returncode == 0, f"hot_forging: exit status {r.returncode}: {r.stderr!r}")
    with open(os.path.join(out, "summary.json")) as f:
        s = strict_json(f)
    c = s.get("coupled", {})
    check(c.get("heat_balance_error", 1.0) < 1e-9, f"hot_forging: heat ledger {c}")
    check(c.get("heat_from_tools_J", 0.0) < 0.0 and c.get("temperature_min_K", 2000.0) < 1373.0, f"hot_forging: no die chill {c}")
    check(c.get("heat_plastic_J", 0.0) > 0.0 and c.get("heat_friction_J", -1.0) >= 0.0, f"hot_forging: sources {c}")
    stored = c.get("heat_plastic_J", 0) + c.get("heat_friction_to_body_J", 0) + c.get("heat_from_tools_J", 0) + \
        c.get("heat_convection_J", 0)
    check(abs(stored - c.get("heat_stored_J", 1e30)) <= 1e-9 * abs(c.get("heat_from_tools_J", 1.0)),
          f"hot_forging: stored heat {c.get('heat_stored_J')} against the flows' sum {stored}")
    check(s.get("scaled_masses", {}).get("quasi_static") is True, f"hot_forging: {s.get('scaled_masses')}")
    with open(os.path.join(out, "history.csv")) as f:
        header = f.readline().strip().split(",")
    check("heat_from_tools_J" in header and "temperature_min_K" in header, f"hot_forging: history columns {header}")
    check(os.path.isfile(os.path.join(out, "final_temperature.png")), "hot_forging: no final_temperature.png")
    print(f"ok  {'hot_forging to 0.05 s':50} -> T min {c.get('temperature_min_K')}, from dies {c.get('heat_from_tools_J')} J")


def ring_compression(rkpm_run, work):
    """cases/ring_compression.json (1.5 s a run) at Coulomb mu = 0 and 0.2 to 50% reduction: with
    no friction the hole grows like the outer diameter (homogeneous flow, sqrt(2) - 1 = +41.4%),
    with mu = 0.2 it shrinks (the ring test's calibration curves, tutorials/15_hot_forging);
    both quasi-static under mass scaling."""
    case = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "cases", "ring_compression.json")
    change = {}
    for mu in (0.0, 0.2):
        out = os.path.join(work, f"ring_mu{mu:g}")
        shutil.rmtree(out, ignore_errors=True)
        r = run([rkpm_run, case, "--set", f"/contact/friction={mu:g}", "--out", out, "--threads", "1", "--quiet", "--no-plots"])
        label = f"ring_compression, mu = {mu:g}"
        check(r.returncode == 0, f"{label}: exit status {r.returncode}: {r.stderr!r}")
        with open(os.path.join(out, "summary.json")) as f:
            s = strict_json(f)
        check(s.get("scaled_masses", {}).get("quasi_static") is True, f"{label}: {s.get('scaled_masses')}")
        with open(os.path.join(out, "history.csv")) as f:
            last = list(csv.DictReader(f))[-1]
        reduction = -2.0 * float(last["die_travel_mm"]) / 10.0
        check(abs(reduction - 0.5) < 1e-6, f"{label}: reduction {reduction}")
        change[mu] = float(last["inner_radius_min_mm"]) / 7.5 - 1.0
    check(abs(change[0.0] - (math.sqrt(2.0) - 1.0)) < 0.02, f"ring_compression: frictionless hole {change[0.0]:+.3f}, homogeneous +0.414")
    check(change[0.2] < -0.1, f"ring_compression: mu = 0.2 hole {change[0.2]:+.3f}, expected to shrink by more than 10%")
    print(f"ok  {'ring_compression mu = 0 and 0.2 to 50%':50} -> inner diameter {change[0.0]:+.3f}, {change[0.2]:+.3f}")


def mass_scaling(rkpm_run, work):
    """A mass-scaled run reports the added mass (factor - 1 times the block's rho W H) and its
    largest kinetic to internal energy ratio; the block forging at 10 m/s with masses times 100
    (a 100 m/s forging's inertia) warns once that it left the quasi-static regime; at 1 m/s with
    masses times 4 (a 2 m/s forging's inertia) it stays quasi-static and says nothing
    (docs/method.md section 5.10). Both to 20% reduction."""
    out = os.path.join(work, "mass_scaling")
    base = ["block_forging", "--set", "particles_per_side=11", "--no-plots", "--quiet"]
    for factor, speed, dynamic in [(100.0, 10.0, True), (4.0, 1.0, False)]:
        shutil.rmtree(out, ignore_errors=True)
        speed_args = ["--set", f"tool_velocity_m_s={speed:g}", "--set", f"end_time_s={0.05 / speed:g}"]
        r = run([rkpm_run] + base + speed_args + ["--mass-scaling-factor", str(factor), "--out", out])
        label = f"block_forging at {speed:g} m/s, masses x {factor:g}"
        check(r.returncode == 0, f"{label}: exit status {r.returncode}: {r.stderr!r}")
        warnings = [line for line in r.stderr.splitlines() if "quasi-static" in line]
        check(len(warnings) == (1 if dynamic else 0), f"{label}: warnings {warnings!r}")
        with open(os.path.join(out, "summary.json")) as f:
            m = strict_json(f).get("scaled_masses", {})
        added = (factor - 1.0) * 8930.0 * 0.5 * 0.5
        check(m.get("factor") == factor, f"{label}: factor {m}")
        check(abs(m.get("added_mass_per_body", [0.0])[0] / added - 1.0) < 1e-9, f"{label}: added mass {m}, expected {added}")
        check(m.get("quasi_static") == (not dynamic), f"{label}: quasi_static {m}")
        check((m.get("max_kinetic_to_internal", 0.0) > 0.05) == dynamic, f"{label}: ratio {m}")
        with open(os.path.join(out, "history.csv")) as f:
            header = f.readline().strip().split(",")
        check(header[-1] == "kinetic_to_internal", f"{label}: history columns end with {header[-3:]}")
        print(f"ok  {label!r:50} -> ratio {m.get('max_kinetic_to_internal')}, warnings {len(warnings)}")


def help_text(rkpm_run):
    r = run([rkpm_run, "--help"])
    check(r.returncode == 0 and "--quadrature" in r.stdout and "--set" in r.stdout, "rkpm_run --help: usage text")
    expected = {
        "taylor_bar": ["velocity_m_s", "radius_m", "height_m", "yield_stress_Pa", "end_time_s", "radial_particles",
                       "axial_particles", "friction"],
        "block_forging": ["tool_velocity_m_s", "width_m", "friction", "particles_per_side", "end_time_s"],
        "wheel_forging": ["tool_velocity_m_s", "stroke_m", "flow_coefficient_Pa", "flow_exponent",
                          "radial_particles"],
        "rod_on_rod": ["velocity_m_s", "radius_m", "lower_height_m", "upper_height_m", "friction", "end_time_s",
                       "radial_particles", "axial_particles", "two_pass"],
    }
    for case, names in expected.items():
        r = run([rkpm_run, case, "--help"])
        check(r.returncode == 0, f"{case} --help: exit status {r.returncode}")
        for name in names:
            check(any(line.split()[:1] == [name] for line in r.stdout.splitlines()),
                  f"{case} --help does not list {name}:\n{r.stdout}")
        # Each parameter line shows a numeric default.
        for line in r.stdout.splitlines():
            parts = line.split()
            if parts and parts[0] in names:
                try:
                    float(parts[1])
                except ValueError:
                    check(False, f"{case} --help: no default value on {line!r}")
    print("ok  help")


def real_run(rkpm_run, out):
    shutil.rmtree(out, ignore_errors=True)
    r = run([rkpm_run, "taylor_bar", "--end-time", repr(END_TIME), "--set", f"axial_particles={AXIAL}",
             "--out", out, "--quiet"])
    print(r.stdout, r.stderr)
    check(r.returncode == 0, f"the short Taylor bar run failed with status {r.returncode}")
    # The same run with LZ4 snapshots, which vtk() decodes and compares with these.
    lz4 = out + "-lz4"
    shutil.rmtree(lz4, ignore_errors=True)
    r = run([rkpm_run, "taylor_bar", "--end-time", repr(END_TIME), "--set", f"axial_particles={AXIAL}",
             "--out", lz4, "--quiet", "--no-plots", "--vtu-compression", "lz4"])
    check(r.returncode == 0, f"the run with --vtu-compression lz4 failed: {r.stderr}")


def reject_constant(name):
    raise ValueError(f"non-standard JSON constant {name} (NaN/Infinity must be written as null)")


def strict_json(f):
    """summary.json parsed as standard JSON (no NaN or Infinity), keys in file order."""
    return json.load(f, parse_constant=reject_constant)


# summary.json's keys in the order the runner writes them (a completed run).
SUMMARY_KEYS = ["case", "kernel", "correction", "quadrature", "geometry", "contact", "resolution", "status",
                "parameters", "particles", "quadrature_points", "steps", "dt_min_s", "dt_max_s", "end_time_s",
                "threads", "processes", "wall_s", "output_s", "setup_s", "energy", "results"]


# summary.json's energy terms (io/solver_output.hpp, docs/method.md section 7).
ENERGY_KEYS = ["kinetic_J", "internal_J", "plastic_J", "contact_J", "external_J", "constraint_J", "initial_kinetic_J",
               "largest_term_J", "balance_error"]


def check_balance_closes(e, label):
    """The printed terms close the ledger to the printed error: |K + W_int - K0 - W_ext - W_contact -
    W_constraint| <= balance_error x largest_term_J (the error is the largest imbalance of the run over
    its largest term; the final imbalance is at most that), up to the 17 printed digits."""
    imbalance = (e["kinetic_J"] + e["internal_J"] - e["initial_kinetic_J"] - e["external_J"] - e["contact_J"] -
                 e["constraint_J"])
    bound = e["balance_error"] * e["largest_term_J"] + 1e-14 * e["largest_term_J"]
    check(abs(imbalance) <= bound, f"{label}: the printed energy terms leave {imbalance} J, more than the printed "
          f"error allows ({bound} J): a term is missing from summary.json")
    return imbalance


def finite(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def outputs(out):
    with open(os.path.join(out, "summary.json")) as f:
        s = strict_json(f)
    check(list(s) == SUMMARY_KEYS, f"summary.json: keys {list(s)}, expected {SUMMARY_KEYS}")
    check(list(s.get("energy", {})) == ENERGY_KEYS, f"summary.json: energy keys {list(s.get('energy', {}))}")
    check(list(s.get("results", {})) == ["radius_mm", "height_mm", "length_mm", "max_equivalent_plastic_strain"],
          f"summary.json: results keys {list(s.get('results', {}))}")
    # Parameters keep their types: counts are integers, quantities are numbers.
    params = s.get("parameters", {})
    check(params.get("axial_particles") == AXIAL and type(params.get("axial_particles")) is int,
          f"summary.json: parameters.axial_particles = {params.get('axial_particles')!r}, expected the integer {AXIAL}")
    check(type(params.get("radial_particles")) is int, "summary.json: parameters.radial_particles is not an integer")
    check(finite(params.get("velocity_m_s")) and params["velocity_m_s"] == VELOCITY, "summary.json: velocity_m_s")
    for key in ["particles", "quadrature_points", "steps", "resolution", "threads"]:
        check(type(s.get(key)) is int, f"summary.json: '{key}' is not an integer: {s.get(key)!r}")
    for key in ["case", "kernel", "correction", "quadrature", "geometry", "contact"]:
        check(isinstance(s.get(key), str), f"summary.json: '{key}' missing or not a string")
    for key in ["particles", "quadrature_points", "steps", "dt_min_s", "dt_max_s", "end_time_s", "threads", "wall_s",
                "setup_s"]:
        check(finite(s.get(key)), f"summary.json: '{key}' missing or not a finite number")
    for key in ENERGY_KEYS:
        check(finite(s.get("energy", {}).get(key)), f"summary.json: 'energy.{key}' missing or not finite")
    for key in ["radius_mm", "height_mm", "length_mm", "max_equivalent_plastic_strain"]:
        check(finite(s.get("results", {}).get(key)), f"summary.json: 'results.{key}' missing or not finite")
    if failures:
        return
    check((s["case"], s["kernel"], s["correction"], s["quadrature"], s["geometry"], s["contact"]) ==
          ("taylor_bar", "cubic", "linear", "q2", "axisymmetric", "paper"), f"summary.json: policies {s}")
    check(s["particles"] == RADIAL * AXIAL, f"particles {s['particles']}, expected {RADIAL} x {AXIAL}")
    # Q2: two points per background cell, (21 - 1) x (21 - 1) cells.
    check(s["quadrature_points"] == 2 * (RADIAL - 1) * (AXIAL - 1), f"quadrature_points {s['quadrature_points']}")
    check(abs(s["end_time_s"] - END_TIME) <= 1e-12 * END_TIME, f"end_time_s {s['end_time_s']}, asked {END_TIME}")
    check(s["steps"] >= 1 and 0 < s["dt_min_s"] <= s["dt_max_s"], f"steps / dt range {s['steps']}, "
          f"{s['dt_min_s']}..{s['dt_max_s']}")
    check(s["steps"] * s["dt_max_s"] >= END_TIME * (1 - 1e-9) and s["steps"] * s["dt_min_s"] <= END_TIME * (1 + 1e-9),
          "steps x dt range does not bracket the end time")
    check(s["threads"] >= 1 and s["processes"] == 1 and s["wall_s"] >= 0 and s["setup_s"] >= 0
          and 0 < s["output_s"] < s["wall_s"], "threads / timings")
    e = s["energy"]
    check(e["balance_error"] < 0.01, f"energy balance error {e['balance_error']}")
    check(e["external_J"] == 0.0, "no body force: external work must be 0")
    check(0 <= e["plastic_J"] <= e["internal_J"], "plastic dissipation must lie in [0, internal work]")
    check(e["contact_J"] <= 0.0, "a fixed frictionless wall only takes energy out")
    # Initial kinetic energy: the bar's mass pi R^2 L rho at 227 m/s.
    k0 = 0.5 * math.pi * (RADIUS_MM * 1e-3) ** 2 * HEIGHT_MM * 1e-3 * 8930.0 * VELOCITY ** 2
    check(abs(e["kinetic_J"] + e["internal_J"] - e["contact_J"] - k0) < 0.01 * k0,
          f"K + W_int - W_contact = {e['kinetic_J'] + e['internal_J'] - e['contact_J']} J, K0 = {k0} J")
    check(abs(e["initial_kinetic_J"] - k0) < 1e-6 * k0, f"initial_kinetic_J {e['initial_kinetic_J']}, expected {k0}")
    check_balance_closes(e, "taylor_bar")
    res = s["results"]
    check(res["radius_mm"] > RADIUS_MM and res["height_mm"] < HEIGHT_MM, f"results {res}")
    check(res["height_mm"] > HEIGHT_MM - 1.01 * VELOCITY * END_TIME * 1e3, f"height {res['height_mm']}")
    check(res["max_equivalent_plastic_strain"] > 0, "the impact face must have yielded")

    with open(os.path.join(out, "history.csv")) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], [[float(v) for v in r] for r in rows[1:]]
    for col in ["time_s", "radius_mm", "height_mm", "kinetic_J", "balance_error"]:
        check(col in header, f"history.csv: no column {col}: {header}")
    check(len(data) >= 10 and all(len(r) == len(header) for r in data), "history.csv: rows")
    t = [r[0] for r in data]
    check(t[0] == 0.0 and all(b > a for a, b in zip(t, t[1:])), "history.csv: time must start at 0 and increase")
    check(abs(t[-1] - END_TIME) <= 1e-12 * END_TIME, f"history.csv: last time {t[-1]}")
    h = header.index("height_mm")
    check(abs(data[-1][h] - res["height_mm"]) < 1e-9, "history.csv's last height differs from summary.json")
    k = header.index("kinetic_J")
    check(abs(data[0][k] - k0) < 1e-6 * k0, f"history.csv: kinetic energy at t = 0 is {data[0][k]}, expected {k0}")

    pngs = [f for f in os.listdir(out) if f.endswith(".png")]
    check(len(pngs) >= 1, "no PNG figure written")
    check("final_plastic_strain.png" in pngs, f"no final_plastic_strain.png among {pngs}")
    for p in pngs:
        with open(os.path.join(out, p), "rb") as f:
            check(f.read(8) == b"\x89PNG\r\n\x1a\n", f"{p} is not a PNG")
    print(f"ok  outputs: {s['particles']} particles, {s['steps']} steps, {len(data)} history rows, PNGs {pngs}")


def vtk(out):
    import numpy as np
    import meshio

    with open(os.path.join(out, "summary.json")) as f:
        s = strict_json(f)
    pvds = [f for f in os.listdir(out) if f.endswith(".pvd")]
    check(pvds == ["taylor_bar.pvd"], f"expected one taylor_bar.pvd, found {pvds}")
    sets = ElementTree.parse(os.path.join(out, pvds[0])).getroot().findall("./Collection/DataSet")
    check(len(sets) >= 2, "the .pvd lists fewer than two snapshots")
    times = [float(d.get("timestep")) for d in sets]
    check(times[0] == 0.0 and all(b > a for a, b in zip(times, times[1:])), f"snapshot times {times}")
    check(abs(times[-1] - s["end_time_s"]) <= 1e-12 * s["end_time_s"], "the last snapshot is not at the end time")
    meshes = []
    for d in sets:
        path = os.path.join(out, d.get("file"))
        check(os.path.exists(path), f"{path} listed in the .pvd does not exist")
        m = meshio.read(path)
        meshes.append(m)
        n = s["particles"]
        check(m.points.shape == (n, 3), f"{path}: points {m.points.shape}, summary says {n} particles")
        shapes = {"displacement": (n, 3), "velocity": (n, 3), "stress": (n, 9), "equivalent_plastic_strain": (n,),
                  "det_F": (n,)}
        for name, shape in shapes.items():
            a = m.point_data.get(name)
            check(a is not None, f"{path}: no point array {name}")
            if a is None:
                continue
            check(a.shape == shape, f"{path}: {name} has shape {a.shape}, expected {shape}")
            check(bool(np.all(np.isfinite(a))), f"{path}: {name} is not finite")
        if failures:
            return
        check(bool(np.all(m.points[:, 2] == 0.0)) and bool(np.all(m.point_data["displacement"][:, 2] == 0.0)),
              f"{path}: a 2D body has z = 0")
        # The particle values are a lumped projection with the RK shape functions, which dip
        # slightly below zero at the edge of their supports: a non-negative field may come out
        # a hair below zero next to a plastic zone, never by more than round-off of its size.
        eps = m.point_data["equivalent_plastic_strain"]
        check(eps.min() >= -1e-6 * max(eps.max(), 1e-12), f"{path}: eps_p down to {eps.min()} (max {eps.max()})")
        det = m.point_data["det_F"]
        check(bool(np.all((det > 0.8) & (det < 1.2))), f"{path}: det F in {det.min()}..{det.max()}")
        stress = m.point_data["stress"].reshape(n, 3, 3)
        check(bool(np.allclose(stress, stress.transpose(0, 2, 1), rtol=0, atol=1e-6 * max(1.0, abs(stress).max()))),
              f"{path}: Cauchy stress is not symmetric")
    first, last = meshes[0], meshes[-1]
    ref = first.points
    # The background cells as VTK quads on the particles: the grid's (RADIAL - 1) x (AXIAL - 1)
    # cells, particle i + RADIAL j at (r_i, z_j), each counter-clockwise in the (r, z) plane
    # (positive area in the reference section), together the section's area R x L.
    quads = [[i + RADIAL * j, i + 1 + RADIAL * j, i + 1 + RADIAL * (j + 1), i + RADIAL * (j + 1)]
             for j in range(AXIAL - 1) for i in range(RADIAL - 1)]
    for m, d in zip(meshes, sets):
        check([c.type for c in m.cells] == ["quad"], f"{d.get('file')}: cell blocks {[c.type for c in m.cells]}")
        check(len(m.cells) == 1 and np.array_equal(m.cells[0].data, np.array(quads)),
              f"{d.get('file')}: the quads are not the grid's cells")
        tools = [k for k in m.field_data if k.startswith("tool:")]
        check(len(tools) == 1, f"{d.get('file')}: tools in <FieldData> {list(m.field_data)}, expected the wall")
    if failures:
        return
    xy = ref[np.array(quads)][..., :2]
    area = 0.5 * np.sum(xy[..., 0] * np.roll(xy[..., 1], -1, axis=1) - np.roll(xy[..., 0], -1, axis=1) * xy[..., 1],
                        axis=1)
    check(bool(np.all(area > 0)), f"quads not counter-clockwise in (r, z): {np.sum(area <= 0)} with area <= 0")
    check(abs(area.sum() - RADIUS_MM * HEIGHT_MM * 1e-6) < 1e-12 * area.sum(), f"quads cover {area.sum()} m^2")
    check(bool(np.all(first.point_data["displacement"] == 0.0)), "the t = 0 snapshot has non-zero displacement")
    # The bar starts in uniform motion at -227 m/s (RK reproduces constants exactly).
    v0 = first.point_data["velocity"]
    check(bool(np.allclose(v0[:, 0], 0.0, atol=1e-9)) and bool(np.allclose(v0[:, 1], -VELOCITY, rtol=1e-12)),
          f"initial velocity {v0[:, 1].min()}..{v0[:, 1].max()}, expected -{VELOCITY}")
    # Reference grid: 21 x 21 particles on [0, R] x [0, L].
    check(abs(ref[:, 0].max() - RADIUS_MM * 1e-3) < 1e-12 and abs(ref[:, 1].max() - HEIGHT_MM * 1e-3) < 1e-12 and
          ref[:, :2].min() == 0.0, "the first snapshot is not the reference section")
    for m, t in zip(meshes, times):
        gap = np.abs(m.points - (ref + m.point_data["displacement"])).max()
        check(gap < 1e-12, f"t = {t}: points differ from reference + displacement by {gap} m")
    x = last.points
    face = ref[:, 1] == 0.0
    radius_mm, height_mm = x[face, 0].max() * 1e3, x[:, 1].max() * 1e3
    res = s["results"]
    check(abs(radius_mm - res["radius_mm"]) < 1e-9 and abs(height_mm - res["height_mm"]) < 1e-9,
          f"the last snapshot gives radius {radius_mm} and height {height_mm} mm; summary.json says {res}")
    # The length is the height less the lowest point (the impact face, pressed a little into the
    # wall here; off it once the bar lifts), not the height.
    lowest_mm = x[:, 1].min() * 1e3
    check(lowest_mm != 0.0 and abs(res["length_mm"] - (height_mm - lowest_mm)) < 1e-9,
          f"the last snapshot gives length {height_mm - lowest_mm} mm (height {height_mm}, lowest point "
          f"{lowest_mm}); summary.json says {res}")
    axis = ref[:, 0] == 0.0
    check(np.abs(x[axis, 0]).max() < 1e-15, "axis particles left r = 0")
    check(x[:, 1].min() > -0.02 * HEIGHT_MM * 1e-3 / (AXIAL - 1), "particles below the wall")
    print(f"ok  vtk: {len(meshes)} snapshots of {s['particles']} particles; final radius {radius_mm:.4f} mm, "
          f"height {height_mm:.4f} mm")
    lz4_snapshots(out, sets, meshes)


def lz4_snapshots(out, sets, meshes):
    """The run with --vtu-compression lz4: every snapshot declares vtkLZ4DataCompressor and, decoded
    by check_vtu.py's own reader (meshio reads no LZ4), holds the zlib run's arrays bit for bit."""
    import numpy as np
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "unit", "io"))
    from check_vtu import compressor_of, decoded_arrays

    lz4 = out + "-lz4"
    for d, m in zip(sets, meshes):
        path = os.path.join(lz4, d.get("file"))
        check(os.path.exists(path), f"{path}: the LZ4 run did not write it")
        if failures:
            return
        check(compressor_of(path) == "vtkLZ4DataCompressor", f"{path}: compressor {compressor_of(path)}")
        arrays = decoded_arrays(path)
        check(np.array_equal(arrays["Points"][0].reshape(-1, 3), m.points), f"{path}: points differ from the zlib run")
        for name, values in m.point_data.items():
            got = arrays.get(name)
            check(got is not None and np.array_equal(got[0].reshape(values.shape), values),
                  f"{path}: {name} differs from the zlib run")
        check(np.array_equal(arrays["connectivity"][0].reshape(-1, 4), m.cells[0].data), f"{path}: cells differ")
    print(f"ok  vtk: the {len(sets)} LZ4 snapshots decode to the zlib snapshots' arrays")


def view(script, out):
    """tools/rkpm view on the run's folder: a PNG of the last snapshot by default, of the snapshot
    nearest --time otherwise, any point field; an unknown field or folder is a one-line error."""
    sets = ElementTree.parse(os.path.join(out, "taylor_bar.pvd")).getroot().findall("./Collection/DataSet")
    last = len(sets) - 1
    times = [float(d.get("timestep")) for d in sets]
    nearest = min(range(len(times)), key=lambda i: abs(times[i] - 0.9e-6))
    cases = [([], f"view_equivalent_plastic_strain_{last:06d}.png"),
             (["--field", "stress"], f"view_stress_{last:06d}.png"),
             (["--field", "velocity:1", "--time", "0.9e-6"], f"view_velocity_1_{nearest:06d}.png"),
             (["--field", "det_F", "--time", "0", "--out", os.path.join(out, "mine.png")], "mine.png")]
    for args, name in cases:
        r = run(["/usr/bin/python3", script, out, *args])
        check(r.returncode == 0, f"view {args}: exit {r.returncode}: {r.stderr}")
        png = r.stdout.strip()
        check(os.path.basename(png) == name, f"view {args}: wrote {png}, expected {name} (the snapshot nearest)")
        check(os.path.isfile(png) and open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n", f"view {args}: {png} no PNG")
        # Drawn: more than the axes and text of an empty plot.
        check(os.path.getsize(png) > 10000, f"view {args}: {png} is only {os.path.getsize(png)} bytes")
    for args, words in [(["--field", "nosuch"], ["nosuch", "equivalent_plastic_strain", "det_F"]),
                        (["--field", "stress:9"], ["components 0 to 8"])]:
        r = run(["/usr/bin/python3", script, out, *args])
        check(r.returncode != 0 and all(w in r.stderr for w in words), f"view {args}: {r.returncode} {r.stderr!r}")
    r = run(["/usr/bin/python3", script, os.path.join(out, "nosuch")])
    check(r.returncode != 0 and "not a folder" in r.stderr, f"view of no folder: {r.stderr!r}")
    print(f"ok  view: {len(cases)} pictures of {out}")


# Rules whose points are not symmetric under z -> -z (the diagonal Gauss pair, the triangles on
# one diagonal): the two rods, mirror images, are integrated by different rules.
DIAGONAL_RULES = ("q2", "q2+vci", "q2_tri")
DENSITY = 8930.0


def rod_on_rod(rkpm_run, work):
    """Two rods head on, small and short, with each --enforcement (and its older name --contact),
    --quadrature, --kernel and --correction. Measured from the snapshots (rod_measures), not from
    summary.json: the run ends; both rods shorten, by the same amount within 3% of the shortening
    with a rule symmetric under z -> -z (measured: within 0.3%), within 30% with a diagonal rule
    (measured: up to 23%, quartic kernel; the rods' rules are mirror images); their faces spread;
    the total axial momentum, zero at the start, stays within 4% of one rod's m |v0| at every
    snapshot (zero to round-off with the solver's masses, which its rule integrates; the 4% is
    this estimate's own error, bilinear on the quads against the rule's masses: measured up to
    1.7% with q2 rules, 1e-4 with q4, q4+vci, q2_split and scni, against the 10% of m |v0| each
    rod has given the other by the end); each rod loses at least 5% of its momentum (the contact
    acted); and no face particle goes deeper than a tenth of a spacing into the other rod's face
    at any snapshot."""
    small = ["--set", "radial_particles=5", "--set", "axial_particles=11", "--end-time", "4e-6", "--no-plots",
             "--quiet", "--threads", "1"]
    spacing_mm = 32.4 / 10
    variants = [["--enforcement", c] for c in ("paper", "effective_mass")] + [["--contact", "penalty"]]
    variants += [["--quadrature", q] for q in ("q4", "q2_split", "q2_tri", "q2+vci", "q4+vci", "scni")]
    variants += [["--kernel", "quartic"], ["--correction", "quadratic", "--set", "support_factor=3"],
                 ["--set", "two_pass=1"],
                 ["--set", "friction=0.3"]]
    for v in variants:
        out = os.path.join(work, "rod_on_rod", "_".join(a.strip("-").replace("+", "") for a in v))
        shutil.rmtree(out, ignore_errors=True)
        extra = ["--set", "penalty_stiffness_N_m=1e9"] if v == ["--contact", "penalty"] else []
        r = run([rkpm_run, "rod_on_rod", *small, *v, *extra, "--out", out])
        check(r.returncode == 0, f"rod_on_rod {v}: exit status {r.returncode}: {r.stderr}")
        if r.returncode != 0:
            continue
        summary = json.load(open(os.path.join(out, "summary.json")))
        if v[0] in ("--enforcement", "--contact"):
            check(summary["contact"] == v[1], f"rod_on_rod {v}: ran with the {summary['contact']} enforcement")
        check_rods(f"rod_on_rod {v}", out, summary, spacing_mm)
    print(f"ok  rod_on_rod: {len(variants)} variants")


def check_rods(label, out, summary, spacing_mm):
    import numpy as np

    before = len(failures)
    heights, momenta, depth = rod_measures(out)
    res = summary["results"]
    lower, upper = heights[0] * 1e3, heights[1] * 1e3
    check(abs(lower - res["lower_final_height_mm"]) < 1e-9 and abs(upper - res["upper_final_height_mm"]) < 1e-9,
          f"{label}: the last snapshot gives heights {lower}, {upper} mm; summary.json {res}")
    shortening = (32.4 - lower, 32.4 - upper)
    check(min(shortening) > 0, f"{label}: the rods did not shorten ({lower}, {upper})")
    mean = 0.5 * sum(shortening)
    asymmetry = abs(shortening[0] - shortening[1]) / mean
    limit = 0.30 if summary["quadrature"] in DIAGONAL_RULES else 0.03
    check(asymmetry < limit, f"{label}: the rods shorten by {shortening[0]:.4f} and {shortening[1]:.4f} mm, "
          f"{100 * asymmetry:.2f}% apart (at most {100 * limit:.0f}% with the {summary['quadrature']} rule)")
    check(res["lower_final_radius_mm"] > 3.2 and res["upper_final_radius_mm"] > 3.2,
          f"{label}: the impact faces did not spread: {res}")
    rod = DENSITY * math.pi * (3.2e-3) ** 2 * 32.4e-3 * 227.0  # one rod's m |v0|
    net = float(np.max(np.abs(momenta.sum(axis=1)))) / rod
    check(abs(momenta[0, 0] - rod) < 1e-9 * rod and abs(momenta[0, 1] + rod) < 1e-9 * rod,
          f"{label}: momenta at t = 0 {momenta[0]}, expected +-{rod}")
    check(net < 0.04, f"{label}: total axial momentum up to {net:.2e} of m |v0| (the rods' at the end "
          f"{momenta[-1] / rod} m |v0|)")
    check(momenta[-1, 0] < 0.95 * rod and momenta[-1, 1] > -0.95 * rod,
          f"{label}: the rods kept their momenta {momenta[-1] / rod} m |v0|: no contact force")
    check(depth < 0.1 * spacing_mm * 1e-3, f"{label}: a face particle {depth * 1e3:.4f} mm inside the other rod")
    print(f"{'ok ' if len(failures) == before else '-- '} {label}: shortening {shortening[0]:.4f}, "
          f"{shortening[1]:.4f} mm ({100 * asymmetry:.2f}% apart), momentum {net:.1e} m|v0|, rods at "
          f"{momenta[-1, 0] / rod:.3f}, {momenta[-1, 1] / rod:.3f}, deepest {depth * 1e3:.4f} mm")


def axial_momentum(mesh, density, part):
    """The axial momentum integral rho0 v_z 2 pi r dA0 of an axisymmetric snapshot read by meshio,
    over its quads in the reference section (points - displacement), the particle velocities
    interpolated bilinearly, 2 x 2 Gauss points: [of the quads where part is true, of the others]."""
    import numpy as np

    X = mesh.points[:, :2] - mesh.point_data["displacement"][:, :2]
    vz = mesh.point_data["velocity"][:, 1]
    quads = mesh.cells[0].data
    corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    p = np.zeros(2)
    for a in (-1 / math.sqrt(3.0), 1 / math.sqrt(3.0)):
        for b in (-1 / math.sqrt(3.0), 1 / math.sqrt(3.0)):
            N = np.array([(1 + s * a) * (1 + t * b) / 4 for s, t in corners])
            dNa = np.array([s * (1 + t * b) / 4 for s, t in corners])
            dNb = np.array([t * (1 + s * a) / 4 for s, t in corners])
            Xq = X[quads]
            ja, jb = np.einsum("k,ckd->cd", dNa, Xq), np.einsum("k,ckd->cd", dNb, Xq)
            w = density * 2 * math.pi * (Xq[..., 0] @ N) * (ja[:, 0] * jb[:, 1] - ja[:, 1] * jb[:, 0])
            pz = w * (vz[quads] @ N)
            p += [pz[part].sum(), pz[~part].sum()]
    return p


def rod_measures(out):
    """What the rod_on_rod run in OUT wrote, measured here from its VTU snapshots (meshio) and
    nothing else: each rod's height (extent in z) at the end; each rod's axial momentum
    (axial_momentum) at every snapshot; and the deepest penetration at any snapshot
    of a particle of one rod's face (z = 0 in the reference) through the other rod's face,
    the polyline through that face's particles."""
    import numpy as np
    import meshio

    sets = ElementTree.parse(os.path.join(out, "rod_on_rod.pvd")).getroot().findall("./Collection/DataSet")
    lower = None
    momenta, depth = [], 0.0
    for d in sets:
        m = meshio.read(os.path.join(out, d.get("file")))
        x = m.points[:, :2]
        X = x - m.point_data["displacement"][:, :2]
        quads = m.cells[0].data
        if lower is None:
            # The rods are the two connected sets of quads: the first quad's rod, grown through
            # shared corners, and the rest; the lower one holds the lowest particle.
            body = np.full(len(x), -1)
            body[quads[0]] = 0
            changed = True
            while changed:
                tagged = np.any(body[quads] == 0, axis=1)
                changed = bool(np.any(body[quads[tagged]] != 0))
                body[quads[tagged]] = 0
            lower = body == 0
            if not lower[np.argmin(X[:, 1])]:
                lower = ~lower
            quad_lower = lower[quads[:, 0]]
        p = axial_momentum(m, DENSITY, quad_lower)
        momenta.append(p)
        # Faces: the particles at z = 0 of each rod, ordered along r.
        faces = []
        for rod in (lower, ~lower):
            on = np.flatnonzero(rod & (np.abs(X[:, 1]) < 1e-12))
            on = on[np.argsort(X[on, 0])]
            faces.append(x[on])
        lo, up = faces
        # Upper face particles below the lower face, lower face particles above the upper face.
        for pts, face, sign in ((up, lo, 1.0), (lo, up, -1.0)):
            inside = (pts[:, 0] >= face[0, 0]) & (pts[:, 0] <= face[-1, 0])
            if np.any(inside):
                z = np.interp(pts[inside, 0], face[:, 0], face[:, 1])
                depth = max(depth, float(np.max(sign * (z - pts[inside, 1]))))
        last_x = x
    heights = [float(np.ptp(last_x[lower, 1])), float(np.ptp(last_x[~lower, 1]))]
    return heights, np.array(momenta), depth


def main(argv):
    mode = argv[1]
    if mode == "bad-options":
        bad_options(argv[2], argv[3])
    elif mode == "help":
        help_text(argv[2])
    elif mode == "step-budget":
        step_budget(argv[2], argv[3])
    elif mode == "run":
        real_run(argv[2], argv[3])
    elif mode == "outputs":
        outputs(argv[2])
    elif mode == "vtk":
        vtk(argv[2])
    elif mode == "view":
        view(argv[2], argv[3])
    elif mode == "rod-on-rod":
        rod_on_rod(argv[2], argv[3])
    else:
        sys.exit(f"unknown mode {mode}")
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
