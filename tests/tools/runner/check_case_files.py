#!/usr/bin/python3
"""Case files through rkpm_run, run by ctest (tests/tools/runner.cmake).

    check_case_files.py paper_CASE RKPM_RUN CASES_DIR WORK_DIR
                                                            cases/CASE.json gives the built-in case's results
                                                            and history bit for bit (the same problem, built
                                                            from the file); paper_override: with an override
                                                            on each side (PAPER_REQUESTS below)
    check_case_files.py restart RKPM_RUN CASES_DIR WORK_DIR a case-file run restarted from its mid-run
                                                            checkpoint gives the uninterrupted run's outputs
    check_case_files.py errors RKPM_RUN CASES_DIR WORK_DIR  a bad file or override stops before any step with
                                                            the file, the JSON pointer and the fix
    check_case_files.py ledger RKPM_RUN CASES_DIR WORK_DIR  summary.json's energy terms close the balance
                                                            when a constraint does the work
    check_case_files.py voce RKPM_RUN CASES_DIR WORK_DIR    the Taylor bar's file with Voce hardening: Q = 0 is
                                                            the linear law, Q > 0 a harder bar
    check_case_files.py johnson_cook RKPM_RUN CASES_DIR WORK_DIR
                                                            cases/taylor_bar_johnson_cook.json, coarse and short:
                                                            the energy balances, the temperature rises and reaches
                                                            history.csv, summary.json and the VTK snapshots (and
                                                            not a J2 file's); each bad Johnson-Cook key stops the
                                                            run with its pointer and fix
    check_case_files.py zerilli_armstrong RKPM_RUN CASES_DIR WORK_DIR
                                                            cases/taylor_copper_za.json, coarse and short, and the
                                                            same bar with bcc constants: the runner takes the
                                                            temperature-carrying material, the energy balances,
                                                            the temperature rises and reaches summary.json and the
                                                            snapshots (no damage field), the length is the height
                                                            less the lowest point; a bad key stops the run with its
                                                            pointer and fix
    check_case_files.py fracture RKPM_RUN CASES_DIR WORK_DIR
                                                            cases/bar_pulled_apart.json: a Johnson-Cook bar whose
                                                            damage opens cracks breaks in two (history.csv's and
                                                            summary.json's fragments go from 1 to 2) keeping its
                                                            momentum; without opens_cracks no fragment columns; a
                                                            bad opens_cracks stops the run with its pointer;
                                                            cases/brittle_bar.json: a Rankine bar breaks in two
                                                            and dissipates G_c H within 10%
    check_case_files.py mesh RKPM_RUN CASES_DIR WORK_DIR    cases/projectile: a body meshed by Gmsh from a .geo
                                                            has the geometry's mass (kinetic energy 1/2 rho A v^2),
                                                            keeps its symmetry line and stays on the wall's side;
                                                            --resolution 2 meshes it again, about 4x the particles
    check_case_files.py bodies RKPM_RUN CASES_DIR WORK_DIR  several bodies: a free impact of two elastic bars of
                                                            different impedance keeps the total momentum (the
                                                            bodies' momentum histories) to round-off, and the
                                                            lighter bar leaves at 1D wave theory's speed;
                                                            cases/plate_impact: the initial kinetic energy is the
                                                            projectile's alone (1/2 rho_Cu A v^2), the energy
                                                            balances, the projectile stays out of the plate; and
                                                            overlapping bodies stop before any step
    check_case_files.py expressions RKPM_RUN CASES_DIR WORK_DIR
                                                            fields as expressions: cases/spinning_disc.json turns
                                                            at w with no net momentum; a tool ramped by a
                                                            velocity_expression and a body force ramped in time
                                                            close the ledger and restart bit for bit; a bad
                                                            expression stops the run with its pointer

The built-in cases (cases/*.hpp) and the case files are two independent descriptions of the same
problems: one in C++, one in JSON through the generic bodies, tools and histories.
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

from checks import check, exit_status, read, run, summary


def compare(typed, from_file, label):
    a, b = summary(typed), summary(from_file)
    for key in ["results", "energy", "steps", "particles", "quadrature_points", "dt_min_s", "dt_max_s"]:
        check(a[key] == b[key], f"{label}: '{key}' differs: built-in {a[key]}, case file {b[key]}")
    check(read(os.path.join(typed, "history.csv")) == read(os.path.join(from_file, "history.csv")),
          f"{label}: history.csv differs")
    print(f"ok  {label}: {b['steps']} steps, results {b['results']}")


def run_document(rkpm_run, doc, work, name, *options):
    """Writes the case document to WORK/NAME.json and runs it into WORK/NAME (no plots, quiet, and
    the options); returns the run and its folder."""
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(doc, f)
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    return run([rkpm_run, path, "--out", out, "--no-plots", "--quiet", *options]), out


def printed_imbalance(e):
    """K + W_int - K0 - W_ext - W_contact - W_constraint from summary.json's energy terms."""
    return (e["kinetic_J"] + e["internal_J"] - e["initial_kinetic_J"] - e["external_J"] - e["contact_J"] -
            e["constraint_J"])


# The paper's cases from their case files against the built-in cases: (case, end time, built-in
# override, the same override as a JSON pointer), one ctest test each (they run side by side).
PAPER_REQUESTS = {
    "paper_taylor_bar": ("taylor_bar", "20e-6", None, None),
    "paper_block_forging": ("block_forging", "0.015", "friction=0.35", "/contact/friction=0.35"),
    "paper_wheel_forging": ("wheel_forging", "2e-4", None, None),
    "paper_override": ("taylor_bar", "10e-6", "yield_stress_Pa=3e8", "/bodies/0/material/yield_stress_Pa=3e8"),
}


def paper(rkpm_run, cases, work, mode):
    case, end, typed_set, file_set = PAPER_REQUESTS[mode]
    label = f"{case} to {end} s" + (f" with {typed_set}" if typed_set else "")
    typed, from_file = os.path.join(work, "typed-" + mode), os.path.join(work, "file-" + mode)
    for d in (typed, from_file):
        shutil.rmtree(d, ignore_errors=True)
    common = ["--end-time", end, "--no-plots", "--quiet"]
    r1 = run([rkpm_run, case, "--out", typed] + common + (["--set", typed_set] if typed_set else []))
    r2 = run([rkpm_run, os.path.join(cases, case + ".json"), "--out", from_file] + common +
             (["--set", file_set] if file_set else []))
    check(r1.returncode == 0 and r2.returncode == 0, f"{label}: a run failed: {r1.stderr} {r2.stderr}")
    if r1.returncode == 0 and r2.returncode == 0:
        compare(typed, from_file, label)
    if mode == "paper_override" and r2.returncode == 0:
        s = summary(from_file)
        check(s["parameters"]["bodies"][0]["material"]["yield_stress_Pa"] == 3e8 and s["case_file"].endswith(".json"),
              "summary.json does not record the overridden document and the file")


def restart(rkpm_run, cases, work):
    full, cont = os.path.join(work, "file-full"), os.path.join(work, "file-cont")
    for d in (full, cont):
        shutil.rmtree(d, ignore_errors=True)
    base = [rkpm_run, os.path.join(cases, "block_forging.json"), "--end-time", "0.004", "--no-plots", "--quiet"]
    r = run(base + ["--checkpoint-interval", "0.002", "--out", full, "--set", "/contact/friction=0.3"])
    check(r.returncode == 0, f"the case-file run failed: {r.stderr}")
    ck = sorted(f for f in os.listdir(full) if f.endswith(".rkpmcp"))
    check(len(ck) == 2, f"expected two checkpoints, found {ck}")
    r = run([rkpm_run, os.path.join(cases, "block_forging.json"), "--restart", os.path.join(full, ck[0]), "--out", cont,
             "--no-plots", "--quiet"])
    check(r.returncode == 0, f"the restart failed: {r.stderr}")
    compare(full, cont, "block_forging.json restarted from " + ck[0])
    r = run([rkpm_run, "block_forging", "--restart", os.path.join(full, ck[0]), "--out", cont])
    check(r.returncode != 0 and "case file" in r.stderr, f"a built-in case took a case file's checkpoint: {r.stderr}")


def errors(rkpm_run, cases, work):
    folder = os.path.join(work, "bad-files")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    with open(os.path.join(cases, "taylor_bar.json")) as f:
        good = json.load(f)
    bad_modulus = json.loads(json.dumps(good))
    bad_modulus["bodies"][0]["material"]["youngs_modulus_Pa"] = -1
    misspelt = json.loads(json.dumps(good))
    misspelt["bodies"][0]["initial_velocity_ms"] = misspelt["bodies"][0].pop("initial_velocity_m_s")
    inside = json.loads(json.dumps(good))
    inside["tools"][0]["polyline_m"] = [[-1e-3, 5e-3], [5e-3, 5e-3]]
    files = {"bad_modulus.json": (bad_modulus, ["/bodies/0/material/youngs_modulus_Pa", "positive"]),
             "misspelt.json": (misspelt, ["/bodies/0/initial_velocity_ms", "initial_velocity_m_s"]),
             "inside.json": (inside, ["/tools/0", "inside"])}
    for name, (doc, words) in files.items():
        path = os.path.join(folder, name)
        with open(path, "w") as f:
            json.dump(doc, f)
        r = run([rkpm_run, path, "--out", os.path.join(folder, "out"), "--no-plots", "--quiet"])
        check(r.returncode != 0 and name in r.stderr, f"{name}: exit {r.returncode}, {r.stderr!r}")
        for w in words:
            check(w in r.stderr, f"{name}: the error does not say {w!r}: {r.stderr!r}")
        print(f"ok  {name}: {r.stderr.strip()}")
    for args, words in [([os.path.join(folder, "nosuch.json")], ["nosuch.json", "no such file"]),
                        ([os.path.join(cases, "taylor_bar.json"), "--set", "/bodies/0/materiel/density_kg_m3=1"],
                         ["/bodies/0/materiel", "material"]),
                        ([os.path.join(cases, "taylor_bar.json"), "--set", "density=1"], ["/POINTER=VALUE"])]:
        r = run([rkpm_run] + args + ["--out", os.path.join(folder, "out"), "--no-plots", "--quiet"])
        check(r.returncode != 0, f"{args}: accepted")
        for w in words:
            check(w in r.stderr, f"{args}: the error does not say {w!r}: {r.stderr!r}")
        print(f"ok  {' '.join(args[1:]) or args[0]}: {r.stderr.strip()}")
    check(not os.path.exists(os.path.join(folder, "out", "history.csv")), "a bad case file started a run")


def mesh(rkpm_run, cases, work):
    import csv
    import math
    radius, length, velocity, density = 5e-3, 20e-3, 150.0, 8930.0  # projectile.geo and .json
    area = radius * length + math.pi * radius ** 2 / 4
    counts = {}
    for k in (1, 2):
        out = os.path.join(work, f"projectile-{k}")
        shutil.rmtree(out, ignore_errors=True)
        plots = [] if k == 1 else ["--no-plots"]  # resolution 1 draws its figures
        r = run([rkpm_run, os.path.join(cases, "projectile", "projectile.json"), "--resolution", str(k),
                 "--end-time", "10e-6", "--out", out, "--quiet", *plots])
        check(r.returncode == 0, f"projectile at resolution {k} failed: {r.stderr}")
        if r.returncode != 0:
            return
        s = summary(out)
        counts[k] = s["particles"]
        with open(os.path.join(out, "history.csv")) as f:
            rows = list(csv.DictReader(f))
        kinetic0 = float(rows[0]["kinetic_J"])
        expected = 0.5 * density * area * velocity ** 2
        check(abs(kinetic0 / expected - 1) < 2e-3,
              f"resolution {k}: initial kinetic energy {kinetic0} J/m, 1/2 rho A v^2 = {expected} J/m")
        check(s["energy"]["balance_error"] < 1e-2, f"resolution {k}: energy balance error {s['energy']}")
        res = s["results"]
        # The symmetry line x = 0 (the physical curve "symmetry", held in x) stays at x = 0: read the
        # last snapshot's points and reference positions with meshio (an independent reader).
        import meshio
        import numpy as np
        last = sorted(f for f in os.listdir(out) if f.endswith(".vtu"))[-1]
        m = meshio.read(os.path.join(out, last))
        reference = m.points[:, :2] - m.point_data["displacement"][:, :2]
        on_line = abs(reference[:, 0]) < 1e-12
        check(on_line.sum() >= 20 * k and abs(m.points[on_line, 0]).max() < 1e-12 and m.points[:, 0].min() > -1e-9,
              f"resolution {k}: the symmetry line moved: {on_line.sum()} particles on it, smallest x "
              f"{m.points[:, 0].min()}")
        # The Gmsh quadrilaterals as VTK quads on the particles (the mesh's nodes), each
        # counter-clockwise in the reference configuration, together the projectile's area, every
        # particle a node of one.
        check([c.type for c in m.cells] == ["quad"], f"resolution {k}: cell blocks {[c.type for c in m.cells]}")
        quads = m.cells[0].data
        xy = reference[quads]
        areas = 0.5 * (xy[..., 0] * np.roll(xy[..., 1], -1, axis=1) - np.roll(xy[..., 0], -1, axis=1) * xy[..., 1]).sum(1)
        check(bool((areas > 0).all()), f"resolution {k}: {(areas <= 0).sum()} quads not counter-clockwise")
        check(abs(areas.sum() / area - 1) < 2e-3, f"resolution {k}: quads cover {areas.sum()} m^2 of {area}")
        check(len(np.unique(quads)) == len(m.points), f"resolution {k}: particles outside every quad")
        if k == 1:
            for png in ("shape.png", "final_plastic_strain.png"):
                check(os.path.isfile(os.path.join(out, png)), f"resolution 1: no {png}")
        check(res["length_mm"] < 25.0 and res["half_width_mm"] > 5.0 and res["wall_force_N_per_m"] > 0,
              f"resolution {k}: the projectile did not shorten and spread on the wall: {res}")
        print(f"ok  projectile at resolution {k}: {s['particles']} particles, kinetic energy {kinetic0:.1f} J/m "
              f"(1/2 rho A v^2 = {expected:.1f}), results {res}")
    check(3.0 < counts[2] / counts[1] < 5.0, f"resolution 2 gives {counts[2]} particles, resolution 1 {counts[1]}")

    # Gmsh is loaded only by runs that mesh (tools/runner/case_file/gmsh_reader.hpp): rkpm_run is
    # not linked with libgmsh, and a reader that cannot be loaded is reported with what to do.
    linked = subprocess.run(["ldd", rkpm_run], capture_output=True, text=True).stdout
    check("libgmsh" not in linked, "rkpm_run is linked with libgmsh, which every run would then load")
    out = os.path.join(work, "projectile-no-reader")
    r = subprocess.run([rkpm_run, os.path.join(cases, "projectile", "projectile.json"), "--end-time", "1e-6",
                        "--out", out, "--quiet"], capture_output=True, text=True, timeout=300,
                       env={**os.environ, "RKPM_GMSH_READER": os.path.join(work, "no_such_module.so")})
    check(r.returncode != 0 and "RKPM_GMSH_READER" in r.stderr and "no_such_module.so" in r.stderr
          and "/bodies/0/shape/mesh/file" in r.stderr,
          f"a missing Gmsh reader: exit {r.returncode}, {r.stderr.strip()}")
    print(f"ok  no libgmsh in rkpm_run; a missing reader: {r.stderr.strip()}")


def bodies(rkpm_run, cases, work):
    import csv
    import math
    V, L, H = 1.0, 10e-3, 1.5e-3
    mats = {"beryllium": (287e9, 1850.0), "steel": (200e9, 7800.0)}

    def bar(name, x0, v):
        E, rho = mats[name]
        return {"name": name,
                "shape": {"rectangle": {"lower_left_m": [x0, 0], "upper_right_m": [x0 + L, H], "particles": [41, 7]}},
                "material": {"law": "elastic", "youngs_modulus_Pa": E, "poisson_ratio": 0.0, "density_kg_m3": rho},
                "initial_velocity_m_s": [v, 0]}

    c_be = math.sqrt(mats["beryllium"][0] / mats["beryllium"][1])
    Z = {k: math.sqrt(E * rho) for k, (E, rho) in mats.items()}
    v_i = (Z["beryllium"] - Z["steel"]) * V / (Z["beryllium"] + Z["steel"])
    doc = {"name": "two_bars", "geometry": "plane_strain", "method": {"contact": "effective_mass"},
           "end_time_s": 1.6 * 2 * L / c_be,
           "bodies": [bar("beryllium", -L, V), bar("steel", 0.0, -V)],
           "contact": {"pairs": [{"slave": "steel", "master": "beryllium"}], "two_pass": True},
           "histories": [{"name": "P_be", "momentum": {"body": "beryllium", "component": "x"}},
                         {"name": "P_steel", "momentum": {"body": "steel", "component": "x"}}]}
    folder = os.path.join(work, "bodies")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    path = os.path.join(folder, "two_bars.json")
    with open(path, "w") as f:
        json.dump(doc, f)
    out = os.path.join(folder, "two_bars")
    r = run([rkpm_run, path, "--out", out, "--no-plots", "--quiet"])
    check(r.returncode == 0, f"two bars: the run failed: {r.stderr}")
    if r.returncode == 0:
        with open(os.path.join(out, "history.csv")) as f:
            rows = list(csv.DictReader(f))
        m_be = mats["beryllium"][1] * L * H
        P0 = float(rows[0]["P_be"]) + float(rows[0]["P_steel"])
        worst = max(abs(float(row["P_be"]) + float(row["P_steel"]) - P0) for row in rows) / (m_be * V)
        after = float(rows[-1]["P_be"]) / m_be
        check(abs(float(rows[0]["P_be"]) / (m_be * V) - 1) < 1e-9,
              f"two bars: the beryllium bar's momentum {rows[0]['P_be']} is not rho L H V = {m_be * V}")
        check(worst < 1e-12, f"two bars: total momentum changed by {worst} of m V")
        check(abs(after - (2 * v_i - V)) < 0.03 * abs(2 * v_i - V),
              f"two bars: beryllium leaves at {after} m/s, wave theory {2 * v_i - V}")
        print(f"ok  two bars in a case file: {len(rows)} rows, momentum change {worst:.2e} of m V, beryllium leaves "
              f"at {after:.4f} m/s (wave theory {2 * v_i - V:.4f})")

    out = os.path.join(folder, "plate_impact")
    r = run([rkpm_run, os.path.join(cases, "plate_impact", "plate_impact.json"), "--out", out, "--no-plots", "--quiet"])
    check(r.returncode == 0, f"plate_impact: the run failed: {r.stderr}")
    if r.returncode == 0:
        s = summary(out)
        with open(os.path.join(out, "history.csv")) as f:
            rows = list(csv.DictReader(f))
        kinetic0, expected = float(rows[0]["kinetic_J"]), 0.5 * 8930.0 * 5e-3 * 10e-3 * 200.0 ** 2
        check(abs(kinetic0 / expected - 1) < 1e-6, f"plate_impact: kinetic energy {kinetic0} J/m at t = 0, the "
                                                     f"projectile's 1/2 rho A v^2 = {expected}")
        check(s["energy"]["balance_error"] < 1e-2, f"plate_impact: energy balance error {s['energy']}")
        res = s["results"]
        check(res["projectile_length_mm"] < 10.0 and res["crater_depth_mm"] > 0 and res["support_force_N_per_m"] > 0
              and res["plate_max_plastic_strain"] > 0, f"plate_impact: {res}")
        # On the centre line the nose and the plate's top, two particles that start at one point,
        # stay apart (to 2% of the 0.25 mm spacing) at every row, while the crater deepens.
        worst = max(float(row["plate_top_y_mm"]) - float(row["nose_y_mm"]) for row in rows)
        check(worst < 0.02 * 0.25, f"plate_impact: the nose went {worst} mm into the plate")
        # The deepest penetration found (in a step's prediction, before contact corrects it): 0.012 mm,
        # 5% of the spacing, at 200 m/s.
        check(res["max_penetration_mm"] < 0.1 * 0.25, f"plate_impact: penetration {res['max_penetration_mm']} mm")
        print(f"ok  plate_impact: {s['particles']} particles, {s['steps']} steps, {s['wall_s']:.1f} s, kinetic "
              f"energy at t = 0 {kinetic0:.2f} J/m (projectile alone {expected:.2f}), results {res}")

    overlap = json.loads(json.dumps(doc))
    overlap["bodies"][1]["shape"]["rectangle"]["lower_left_m"] = [-1e-3, 0]
    path = os.path.join(folder, "overlap.json")
    with open(path, "w") as f:
        json.dump(overlap, f)
    r = run([rkpm_run, path, "--out", os.path.join(folder, "overlap"), "--no-plots", "--quiet"])
    check(r.returncode != 0 and "overlap.json: /bodies/1/shape: body 'steel' overlaps body 'beryllium'" in r.stderr,
          f"overlapping bodies: exit {r.returncode}, {r.stderr!r}")
    check(not os.path.exists(os.path.join(folder, "overlap", "history.csv")), "overlapping bodies started a run")
    print(f"ok  overlap.json: {r.stderr.strip()}")


def ledger(rkpm_run, cases, work):
    """summary.json's energy terms close the ledger to its printed error (docs/method.md section 7,
    io/solver_output.hpp) in a run where a prescribed motion does the work: the Taylor bar at rest,
    no wall, pushed up from its bottom edge at 100 m/s by an edge constraint. All the energy
    the bar gains is the constraint's work, so a summary without constraint_J cannot balance."""
    with open(os.path.join(cases, "taylor_bar.json")) as f:
        doc = json.load(f)
    doc["tools"] = []
    doc["bodies"][0]["initial_velocity_m_s"] = [0, 0]
    doc["bodies"][0]["constraints"] = [{"edge": "bottom", "velocity_m_s": [None, 100]}]
    r, out = run_document(rkpm_run, doc, work, "pushed_bar", "--end-time", "20e-6")
    check(r.returncode == 0, f"pushed bar: the run failed: {r.stderr}")
    if r.returncode != 0:
        return
    e = summary(out)["energy"]
    imbalance = printed_imbalance(e)
    bound = (e["balance_error"] + 1e-14) * e["largest_term_J"]
    check(abs(imbalance) <= bound, f"pushed bar: the printed terms leave {imbalance} J, more than the printed error "
          f"allows ({bound} J)")
    check(e["constraint_J"] > 0.5 * (e["kinetic_J"] + e["internal_J"]),
          f"pushed bar: the constraint did {e['constraint_J']} J, the bar holds {e['kinetic_J'] + e['internal_J']} J")
    check(e["contact_J"] == 0.0 and e["external_J"] == 0.0, f"pushed bar: no tool, no body force: {e}")
    print(f"ok  pushed bar: constraint work {e['constraint_J']:.4f} J, K + W_int - K0 = "
          f"{e['kinetic_J'] + e['internal_J'] - e['initial_kinetic_J']:.4f} J, imbalance {imbalance:.2e} J "
          f"<= {bound:.2e} J")


def voce(rkpm_run, cases, work):
    """The Taylor bar's case file with Voce hardening (docs/method.md (24a)): with Q = 0 it is the
    linear law (sigma_0 = 400 MPa, H = 100 MPa), so the run must give the built-in case's results to
    the return mapping's tolerance (Newton to 1e-12 instead of the closed form); with Q = 300 MPa
    saturating at b = 10 the bar is harder, so it spreads and shortens less."""
    with open(os.path.join(cases, "taylor_bar.json")) as f:
        doc = json.load(f)
    runs = {}
    for label, saturation in [("no_saturation", 0.0), ("saturating", 300e6)]:
        d = json.loads(json.dumps(doc))
        d["bodies"][0]["material"] = {"law": "j2", "hardening": "voce", "youngs_modulus_Pa": 117e9,
                                      "poisson_ratio": 0.35, "density_kg_m3": 8930, "yield_stress_Pa": 400e6,
                                      "saturation_stress_Pa": saturation, "saturation_rate": 10.0,
                                      "hardening_modulus_Pa": 100e6}
        r, out = run_document(rkpm_run, d, work, "voce_" + label, "--end-time", "20e-6")
        check(r.returncode == 0, f"voce ({label}): the run failed: {r.stderr}")
        if r.returncode != 0:
            return
        runs[label] = summary(out)
    linear = os.path.join(work, "voce-linear")
    shutil.rmtree(linear, ignore_errors=True)
    r = run([rkpm_run, "taylor_bar", "--out", linear, "--end-time", "20e-6", "--no-plots", "--quiet"])
    check(r.returncode == 0, f"taylor_bar: the run failed: {r.stderr}")
    if r.returncode != 0:
        return
    a, b = summary(linear)["results"], runs["no_saturation"]["results"]
    for key in a:
        check(abs(a[key] - b[key]) <= 1e-9 * abs(a[key]), f"voce with Q = 0: {key} {b[key]}, linear {a[key]}")
    hard = runs["saturating"]["results"]
    check(hard["radius_mm"] < b["radius_mm"] and hard["height_mm"] > b["height_mm"] and
          hard["max_equivalent_plastic_strain"] < b["max_equivalent_plastic_strain"],
          f"voce with Q = 300 MPa is not harder than with Q = 0: {hard} against {b}")
    print(f"ok  voce: Q = 0 gives the linear law's {b}; Q = 300 MPa {hard}")


def johnson_cook(rkpm_run, cases, work):
    """The Johnson-Cook Taylor bar (docs/method.md section 4.5) on 9 x 15 particles for 8 us: the
    ledger closes to its printed error with the heat inside the plastic work, the temperature rises
    above room temperature and appears as max_temperature_K in history.csv (rising), in summary.json
    ("points" and the history's result) and as a point field of the snapshots; a J2 file's snapshots
    have no temperature. Bad keys stop the run before any step with the JSON pointer and the fix."""
    with open(os.path.join(cases, "taylor_bar_johnson_cook.json")) as f:
        doc = json.load(f)
    doc["bodies"][0]["shape"]["rectangle"]["particles"] = [9, 15]
    doc["output"] = {"snapshots": 2, "history_rows": 40}
    r, out = run_document(rkpm_run, doc, work, "jc_small", "--end-time", "8e-6")
    check(r.returncode == 0, f"johnson_cook: the run failed: {r.stderr}")
    if r.returncode != 0:
        return
    s = summary(out)
    e = s["energy"]
    imbalance = printed_imbalance(e)
    check(abs(imbalance) <= (e["balance_error"] + 1e-14) * e["largest_term_J"], f"johnson_cook: imbalance {imbalance}")
    check(e["balance_error"] < 2e-2, f"johnson_cook: balance error {e['balance_error']}")
    check(e["plastic_J"] > 0.05 * e["initial_kinetic_J"], f"johnson_cook: little plastic work {e}")
    points = s.get("points", {})
    T = points.get("max_temperature_K", 0.0)
    check(T > 300.0 and T < 1356.0, f"johnson_cook: summary.json points {points}")
    check(s["results"].get("max_temperature_K") == T, f"johnson_cook: results {s['results']} against points {points}")
    check(points.get("failed_fraction") == 0.0 and s["results"].get("failed_fraction") == 0.0,
          f"johnson_cook: a compressed copper bar should not fail: {points}")
    rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
    temps = [float(row["max_temperature_K"]) for row in rows]
    check(temps[0] == 294.0 and all(b >= a for a, b in zip(temps, temps[1:])) and temps[-1] == T,
          f"johnson_cook: max_temperature_K over time {temps[:3]} ... {temps[-3:]}")
    vtus = sorted(f for f in os.listdir(out) if f.endswith(".vtu"))
    text = read(os.path.join(out, vtus[-1]), "rb")
    check(b'Name="temperature_K"' in text and b'Name="damage"' in text, f"johnson_cook: {vtus[-1]} has no temperature")
    j2 = os.path.join(work, "j2_fields")
    shutil.rmtree(j2, ignore_errors=True)
    r = run([rkpm_run, os.path.join(cases, "taylor_bar.json"), "--out", j2, "--end-time", "1e-6", "--no-plots",
             "--quiet"])
    check(r.returncode == 0, f"taylor_bar.json: {r.stderr}")
    vtus = sorted(f for f in os.listdir(j2) if f.endswith(".vtu"))
    check(b"temperature_K" not in read(os.path.join(j2, vtus[-1]), "rb"), "a J2 file's snapshot lists a temperature")
    print(f"ok  johnson_cook: {s['steps']} steps, max temperature {T:.1f} K, plastic {e['plastic_J']:.3f} J of "
          f"{e['initial_kinetic_J']:.3f} J, balance error {e['balance_error']:.2e}")

    material = doc["bodies"][0]["material"]
    bad = []

    def variant(name, change, words):
        d = json.loads(json.dumps(doc))
        change(d["bodies"][0]["material"])
        bad.append((name, d, words))
    variant("negative_B", lambda m: m.update(B_Pa=-1e6), ["/bodies/0/material/B_Pa", "must not be negative"])
    variant("n_above_1", lambda m: m.update(n=1.5), ["/bodies/0/material/n", "(0, 1]", "0.31"])
    variant("n_zero", lambda m: m.update(n=0), ["/bodies/0/material/n", "(0, 1]"])
    variant("melt_below_room", lambda m: m.update(melt_temperature_K=250),
            ["/bodies/0/material/melt_temperature_K", "not above room_temperature_K", "1356"])
    variant("damage_missing_D3", lambda m: m["damage"].pop("D3"), ["/bodies/0/material/damage", "missing field 'D3'",
                                                                   "-3.03"])
    variant("taylor_quinney", lambda m: m.update(taylor_quinney=1.5), ["/bodies/0/material/taylor_quinney", "[0, 1]"])
    variant("missing_heat", lambda m: m.pop("specific_heat_J_kgK"), ["missing field 'specific_heat_J_kgK'", "383"])
    variant("j2_key", lambda m: m.update(yield_stress_Pa=1e8), ["/bodies/0/material/yield_stress_Pa", "unknown field"])
    d = json.loads(json.dumps(doc))
    d["bodies"][0]["material"] = {"law": "j2", "hardening": "linear", "youngs_modulus_Pa": 117e9,
                                  "poisson_ratio": 0.35, "density_kg_m3": 8930, "yield_stress_Pa": 400e6,
                                  "hardening_modulus_Pa": 100e6}
    bad.append(("temperature_of_j2", d, ["/histories/4/max_temperature/body", "no temperature", "johnson_cook"]))
    for name, d, words in bad:
        r, _ = run_document(rkpm_run, d, work, f"jc_{name}")
        check(r.returncode != 0, f"{name}: accepted")
        for w in words:
            check(w in r.stderr, f"{name}: the error does not say {w!r}: {r.stderr!r}")
        print(f"ok  {name}: {r.stderr.strip()}")


def fracture(rkpm_run, cases, work):
    """cases/bar_pulled_apart.json (docs/method.md (32f), section 5.12): the bar's points fail in
    tension at its middle and cut their cells, so history.csv's fragments go from 1 to 2 and the
    largest piece's mass from the bar's to about half; summary.json says the same at the end, with
    the remap term of the rebuilds in its energy; the momentum history stays at its start to
    round-off. With opens_cracks off, the failed points cut nothing and the outputs have no
    fragment columns; a value that is not true or false stops the run with its pointer. And
    cases/brittle_bar.json: a Rankine bar breaks in two, dissipating G_c H."""
    path = os.path.join(cases, "bar_pulled_apart.json")
    out = os.path.join(work, "bar_pulled_apart")
    shutil.rmtree(out, ignore_errors=True)
    r = run([rkpm_run, path, "--out", out, "--no-plots", "--quiet"])
    check(r.returncode == 0, f"fracture: the run failed: {r.stderr}")
    if r.returncode != 0:
        return
    s = summary(out)
    rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
    pieces = [float(row["fragments"]) for row in rows]
    largest = [float(row["largest_fragment_mass_kg"]) for row in rows]
    check(pieces[0] == 1.0 and pieces[-1] == 2.0 and all(b >= a for a, b in zip(pieces, pieces[1:])),
          f"fracture: fragments over time {pieces}")
    check(0.4 * largest[0] < largest[-1] < 0.75 * largest[0], f"fracture: largest fragment mass {largest[0]} -> {largest[-1]}")
    check(s.get("fragments") == 2.0 and s.get("largest_fragment_mass_kg") == largest[-1],
          f"fracture: summary.json fragments {s.get('fragments')}, {s.get('largest_fragment_mass_kg')}")
    check("remap_J" in s["energy"] and s.get("rereferences", 0) >= 1, f"fracture: summary.json {s['energy']}")
    momentum = [float(row["momentum_x_N_s"]) for row in rows]
    scale = largest[0] * 50.0  # the bar's mass times the halves' speed
    check(max(abs(p - momentum[0]) for p in momentum) <= 1e-12 * scale, f"fracture: momentum {momentum[:2]} ... {momentum[-2:]}")
    print(f"ok  bar_pulled_apart.json: {s['steps']} steps, fragments {pieces[0]:g} -> {pieces[-1]:g}, largest "
          f"{largest[-1] / largest[0]:.3f} of the mass, {s['rereferences']} rebuilds")

    joined = os.path.join(work, "bar_joined")
    shutil.rmtree(joined, ignore_errors=True)
    r = run([rkpm_run, path, "--out", joined, "--no-plots", "--quiet", "--set",
             "/bodies/0/material/damage/opens_cracks=false"])
    check(r.returncode == 0, f"fracture: the run without opens_cracks failed: {r.stderr}")
    if r.returncode == 0:
        s = summary(joined)
        header = open(os.path.join(joined, "history.csv")).readline()
        check("fragments" not in header and "fragments" not in s, f"fracture: fragments without opens_cracks: {header}")
        check(s["points"]["failed_fraction"] > 0.0, f"fracture: no point failed without opens_cracks: {s['points']}")
        print(f"ok  without opens_cracks: failed fraction {s['points']['failed_fraction']:.3f}, no fragment columns")

    r = run([rkpm_run, path, "--out", os.path.join(work, "bar_bad"), "--no-plots", "--quiet", "--set",
             "/bodies/0/material/damage/opens_cracks=\"yes\""])
    words = ["/bodies/0/material/damage/opens_cracks", "true or false"]
    check(r.returncode != 0 and all(w in r.stderr for w in words), f"fracture: a bad opens_cracks: {r.stderr!r}")
    print(f"ok  bad opens_cracks: {r.stderr.strip()}")

    # cases/brittle_bar.json: a Rankine bar (docs/method.md section 4.7) thrown apart breaks in two
    # and dissipates G_c H per metre of depth (its crack band follows the kernel's support, (107)).
    path = os.path.join(cases, "brittle_bar.json")
    out = os.path.join(work, "brittle_bar")
    shutil.rmtree(out, ignore_errors=True)
    r = run([rkpm_run, path, "--out", out, "--no-plots", "--quiet"])
    check(r.returncode == 0, f"fracture: the brittle bar failed: {r.stderr}")
    if r.returncode == 0:
        s = summary(out)
        rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
        G_c, H = 500.0, 4e-3
        dissipated = s["energy"]["plastic_J"]
        check(s.get("fragments") == 2.0, f"fracture: the brittle bar's fragments {s.get('fragments')}")
        check(abs(dissipated - G_c * H) <= 0.1 * G_c * H,
              f"fracture: the brittle bar dissipated {dissipated} J/m against G_c H = {G_c * H}")
        momentum = [float(row["momentum_x_N_s"]) for row in rows]
        scale = 1180.0 * 20e-3 * H * 10.0  # the bar's mass per metre times the halves' speed
        check(max(abs(p - momentum[0]) for p in momentum) <= 1e-12 * scale,
              f"fracture: the brittle bar's momentum {momentum[:2]} ... {momentum[-2:]}")
        print(f"ok  brittle_bar.json: {s['steps']} steps, 2 pieces, dissipated {dissipated:.4f} J/m against G_c H = "
              f"{G_c * H:g}, balance {s['energy']['balance_error']:.2e}")


def zerilli_armstrong(rkpm_run, cases, work):
    with open(os.path.join(cases, "taylor_copper_za.json")) as f:
        doc = json.load(f)
    doc["bodies"][0]["shape"]["rectangle"]["particles"] = [9, 15]
    doc["output"] = {"snapshots": 2, "history_rows": 40}
    bcc = json.loads(json.dumps(doc))
    m = bcc["bodies"][0]["material"]
    m.pop("C2_Pa")  # Armco iron's constants (Zerilli & Armstrong 1987), C0 chosen here
    m.update(lattice="bcc", C0_Pa=50e6, C1_Pa=1033e6, C3_1_K=0.00698, C4_1_K=0.000415, C5_Pa=266e6, n=0.289,
             melt_temperature_K=1811)
    for name, d in (("za_fcc", doc), ("za_bcc", bcc)):
        r, out = run_document(rkpm_run, d, work, name, "--end-time", "8e-6")
        check(r.returncode == 0, f"{name}: the run failed: {r.stderr}")
        if r.returncode != 0:
            continue
        s = summary(out)
        e, res = s["energy"], s["results"]
        check(e["balance_error"] < 2e-2, f"{name}: balance error {e['balance_error']}")
        check(e["plastic_J"] > 0.05 * e["initial_kinetic_J"], f"{name}: little plastic work {e}")
        T = s.get("points", {}).get("max_temperature_K", 0.0)
        check(300.0 < T < 1356.0 and res.get("max_temperature_K") == T, f"{name}: temperature {T}, results {res}")
        check(0.0 < res["length_mm"] and abs(res["length_mm"] - res["height_mm"]) < 0.05, f"{name}: results {res}")
        vtus = sorted(f for f in os.listdir(out) if f.endswith(".vtu"))
        text = read(os.path.join(out, vtus[-1]), "rb")
        check(b'Name="temperature_K"' in text and b'Name="damage"' not in text,
              f"{name}: {vtus[-1]} should have a temperature and no damage")
        print(f"ok  {name}: {s['steps']} steps, max temperature {T:.1f} K, length {res['length_mm']:.3f} mm, "
              f"plastic {e['plastic_J']:.3f} J of {e['initial_kinetic_J']:.3f} J, balance error {e['balance_error']:.2e}")

    bad = []

    def variant(name, base, change, words):
        d = json.loads(json.dumps(base))
        change(d["bodies"][0]["material"])
        bad.append((name, d, words))
    variant("lattice", doc, lambda m: m.update(lattice="hcp"), ["/bodies/0/material/lattice", "unknown lattice 'hcp'"])
    variant("bcc_key_in_fcc", doc, lambda m: m.update(C5_Pa=266e6), ["/bodies/0/material/C5_Pa", "unknown field"])
    variant("missing_n", bcc, lambda m: m.pop("n"), ["/bodies/0/material", "missing field 'n'", "0.289"])
    variant("negative_C3", doc, lambda m: m.update(C3_1_K=-1e-3), ["/bodies/0/material/C3_1_K", "must not be negative"])
    variant("melt", doc, lambda m: m.update(melt_temperature_K=200), ["/bodies/0/material/melt_temperature_K",
                                                                       "not above initial_temperature_K"])
    variant("no_initial_temperature", doc, lambda m: m.pop("initial_temperature_K"),
            ["missing field 'initial_temperature_K'", "294"])
    for name, d, words in bad:
        r, _ = run_document(rkpm_run, d, work, f"za_{name}")
        check(r.returncode != 0, f"{name}: accepted")
        for w in words:
            check(w in r.stderr, f"{name}: the error does not say {w!r}: {r.stderr!r}")
        print(f"ok  {name}: {r.stderr.strip()}")


def expressions(rkpm_run, cases, work):
    """Fields given as expressions (tools/runner/case_file/README.md, "Expressions"):
    cases/spinning_disc.json for a quarter turn: the momentum kept, the rim particle turned by about
    w t, the ledger closed; the block forging with its top tool ramped to speed by a
    velocity_expression and a body force ramped in time: the ledger closes with the work of a
    varying body force, and a restart from the mid-run checkpoint gives the uninterrupted run's
    outputs bit for bit (the tool's displacement and the body force are functions of t alone);
    a bad expression stops the run before any step with its pointer."""
    out = os.path.join(work, "spinning_disc")
    shutil.rmtree(out, ignore_errors=True)
    r = run([rkpm_run, os.path.join(cases, "spinning_disc.json"), "--end-time", "8e-5", "--out", out, "--no-plots",
             "--quiet"])
    check(r.returncode == 0, f"spinning_disc.json: the run failed: {r.stderr}")
    if r.returncode == 0:
        s = summary(out)
        w, R, t = 2e4, 10e-3, s["end_time_s"]
        res = s["results"]
        turned = math.atan2(res["rim_y_mm"], res["rim_x_mm"])
        # The momentum is that of the mesh's centre of mass (about, not exactly, at the centre):
        # constant, to round-off of the particles' m w R.
        mass = 7800 * math.pi * R * R  # per metre, about (a 32-gon)
        rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
        P = [float(row["momentum_x_N_s"]) for row in rows]
        check(len(P) > 10 and max(P) - min(P) < 1e-12 * mass * w * R and abs(P[0]) < 1e-3 * mass * w * R,
              f"spinning disc: momentum from {P[0]} to {P[-1]} N s")
        check(abs(turned - w * t) < 0.02 * w * t, f"spinning disc: turned {turned} rad, w t = {w * t}")
        e = s["energy"]
        check(e["balance_error"] < 1e-3, f"spinning disc: balance error {e['balance_error']}")
        print(f"ok  spinning_disc.json: {s['steps']} steps, turned {turned:.4f} rad (w t = {w * t:.4f}), "
              f"momentum {P[0]:.6e} N s changed by {max(P) - min(P):.1e}, balance error {e['balance_error']:.2e}")

    with open(os.path.join(cases, "block_forging.json")) as f:
        doc = json.load(f)
    doc["constants"] = {"v": 10, "T": 1e-3}
    doc["tools"][1]["motion"] = {"type": "velocity_expression", "velocity_m_s": [0, "-v * min(1, t / T)"]}
    doc["bodies"][0]["body_force_m_s2"] = ["0", "-2e3 * min(1, t / T) * (1 + x)"]
    doc["histories"].append({"name": "top_tool_y_mm", "tool_displacement": {"tool": "top_tool", "component": "y",
                                                                              "scale": 1e3}})
    r, full = run_document(rkpm_run, doc, work, "ramped", "--end-time", "0.004", "--checkpoint-interval", "0.002")
    check(r.returncode == 0, f"ramped block: the run failed: {r.stderr}")
    if r.returncode != 0:
        return
    s = summary(full)
    u = s["results"]["top_tool_y_mm"] * 1e-3
    t, v, T = s["end_time_s"], 10.0, 1e-3
    check(abs(u + v * (t - T / 2)) < 1e-12 * v * t, f"ramped block: the top tool moved {u} m, not {-v * (t - T / 2)}")
    e = s["energy"]
    imbalance = printed_imbalance(e)
    check(e["external_J"] != 0.0 and abs(imbalance) <= (e["balance_error"] + 1e-14) * e["largest_term_J"],
          f"ramped block: external work {e['external_J']} J, imbalance {imbalance} J")
    check(e["balance_error"] < 1e-2, f"ramped block: balance error {e['balance_error']}")
    ck = sorted(f for f in os.listdir(full) if f.endswith(".rkpmcp"))
    check(len(ck) == 2, f"ramped block: expected two checkpoints, found {ck}")
    if ck:
        cont = os.path.join(work, "ramped-cont")
        shutil.rmtree(cont, ignore_errors=True)
        r = run([rkpm_run, os.path.join(work, "ramped.json"), "--restart", os.path.join(full, ck[0]), "--out", cont,
                 "--no-plots", "--quiet"])
        check(r.returncode == 0, f"ramped block: the restart failed: {r.stderr}")
        if r.returncode == 0:
            compare(full, cont, "ramped block restarted from " + ck[0])

    doc["bodies"][0]["initial_velocity_m_s"] = ["0", "2 +* x"]
    r, _ = run_document(rkpm_run, doc, work, "bad_expression")
    words = ["bad_expression.json: /bodies/0/initial_velocity_m_s/1:", "does not parse", "position 3"]
    check(r.returncode != 0 and all(w in r.stderr for w in words) and r.stderr.strip().count("\n") == 0,
          f"bad expression: {r.stderr!r}")
    print(f"ok  bad_expression.json: {r.stderr.strip()}")


def main(argv):
    mode, rkpm_run, cases, work = argv[1:5]
    os.makedirs(work, exist_ok=True)
    if mode in PAPER_REQUESTS:
        paper(rkpm_run, cases, work, mode)
        return exit_status()
    { "restart": restart, "errors": errors, "mesh": mesh, "bodies": bodies,
     "ledger": ledger, "voce": voce, "johnson_cook": johnson_cook, "zerilli_armstrong": zerilli_armstrong,
     "fracture": fracture,
     "expressions": expressions}[mode](
        rkpm_run, cases, work)
    return exit_status()


if __name__ == "__main__":
    sys.exit(main(sys.argv))
