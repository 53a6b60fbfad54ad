#!/usr/bin/env python3
"""Tests of the Python module rkpm (tools/python): run by ctest as
    check_python.py MODE MODULE_DIR RKPM_RUN WORK_DIR
with the module's folder on sys.path. Modes:
  same-as-cli  the Taylor bar through rkpm.run and through rkpm_run: summary.json's results,
               energies and steps equal to the last digit; history equal to history.csv;
               the final particles equal to the last VTU snapshot (read by meshio)
  dict-case    a case file's content given as a dict (with a change), run in the same process
  sweep        three impact speeds in one process: the parameters taken, the bar moves further
               and the plastic strain and the wall's impulse grow with speed; the momentum from
               the snapshots is m v at t = 0 and then falls by the wall's impulse (history)
  observer     an observer sees the particles every `every` steps (read-only arrays) and stops
               the run by returning False: status "stopped", the run ends at that step
  errors       CaseError for a bad field, an unknown parameter, a bad policy; RunError for a run
               that fails (with the step); Ctrl-C stops after the step under way and raises
               KeyboardInterrupt; an observer's exception reaches the caller
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys

MODE, MODULE_DIR, RKPM_RUN, WORK = sys.argv[1:5]
sys.path.insert(0, MODULE_DIR)
import numpy as np  # noqa: E402
import rkpm  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
SHORT = {"axial_particles": 21}  # the runner test's short bar: 21 x 21 particles
END = 2e-6
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL", what)


def fresh(name):
    d = os.path.join(WORK, name)
    shutil.rmtree(d, ignore_errors=True)
    return d


def same_as_cli():
    cli_out, py_out = fresh("cli"), fresh("python")
    r = subprocess.run([RKPM_RUN, "taylor_bar", "--end-time", repr(END), "--set", "axial_particles=21", "--out",
                        cli_out, "--quiet", "--no-plots", "--threads", "1"], capture_output=True, text=True)
    check(r.returncode == 0, f"rkpm_run failed: {r.stderr}")
    res = rkpm.run("taylor_bar", set=SHORT, end_time=END, out=py_out, plots=False, threads=1)
    with open(os.path.join(cli_out, "summary.json")) as f:
        cli = json.load(f)
    py = res.summary
    for key in ("case", "kernel", "correction", "quadrature", "contact", "particles", "steps", "dt_min_s",
                "dt_max_s", "end_time_s", "energy", "results", "parameters"):
        check(cli[key] == py[key], f"summary[{key}]: CLI {cli[key]} != Python {py[key]}")
    check(res.completed and py["status"] == "completed", f"status {py['status']}")
    # history: the arrays equal history.csv (written with 17 digits)
    with open(os.path.join(cli_out, "history.csv")) as f:
        rows = list(csv.reader(f))
    header, values = rows[0], np.array([[float(x) for x in row] for row in rows[1:]])
    check(list(res.history) == header, f"history columns {list(res.history)} != {header}")
    for j, name in enumerate(header):
        check(np.array_equal(res.history[name], values[:, j]), f"history column {name} differs from history.csv")
    # final particles: the last snapshot of the CLI run, read by an independent reader
    import meshio
    with open(os.path.join(cli_out, "taylor_bar.pvd")) as f:
        last = [line.split('file="')[1].split('"')[0] for line in f if 'file="' in line][-1]
    mesh = meshio.read(os.path.join(cli_out, last))
    n = res.positions.shape[0]
    check(res.positions.shape == (n, 2) and n == py["particles"], f"positions shape {res.positions.shape}")
    check(np.array_equal(mesh.points[:, :2], res.positions), "final positions differ from the last snapshot")
    check(np.array_equal(mesh.point_data["displacement"][:, :2], res.displacement), "displacement differs")
    check(np.array_equal(mesh.point_data["velocity"][:, :2], res.velocity), "velocity differs")
    s9 = mesh.point_data["stress"].reshape(n, 9)
    check(np.array_equal(s9[:, [0, 4, 8, 1]], res.stress), "stress (xx, yy, zz, xy) differs")
    check(np.array_equal(mesh.point_data["equivalent_plastic_strain"], res.plastic_strain), "plastic strain differs")
    check(res.displacement.flags.writeable, "the result's arrays are the caller's")
    check(res.time_s == py["end_time_s"] and res.step == py["steps"], "time and step of the final state")


def dict_case():
    with open(os.path.join(REPO, "cases", "taylor_bar.json")) as f:
        doc = json.load(f)
    doc["name"] = "slow_bar"
    doc["bodies"][0]["shape"]["rectangle"]["particles"] = [11, 21]
    doc["bodies"][0]["initial_velocity_m_s"] = [0, -100]
    doc["end_time_s"] = END
    res = rkpm.run(doc, out=fresh("dict"), plots=False)
    check(res.summary["case"] == "slow_bar", f"case name {res.summary['case']}")
    check(res.summary["particles"] == 11 * 21, f"particles {res.summary['particles']}")
    # at t = 0 every particle moves at -100 m/s: the mean velocity then falls only by the wall's impulse
    v_top = res.velocity[np.argmax(res.positions[:, 1]), 1]
    check(abs(v_top + 100.0) < 1.0, f"the far end still moves at about -100 m/s after 2 us: {v_top}")


def sweep():
    """Three speeds; for each, the bar's axial momentum P(t) (check_runner.axial_momentum: from the
    VTU snapshots the run wrote, read by meshio) against Newton's second law with the wall the only
    external force: P(0) = -m v to round-off (the initial velocity is uniform), and at every
    snapshot P(t) = P(0) - J(t), J the impulse of the force on the wall (history's wall_force_y_N,
    trapezoids over every step), within 1% of m v: the momentum estimate interpolates the
    particle velocities bilinearly (measured: up to 0.45% of m v at each speed, where J is 8-9%)."""
    sys.path.insert(0, os.path.join(REPO, "tests", "tools", "runner"))
    import xml.etree.ElementTree as ElementTree
    import meshio
    from check_runner import axial_momentum

    results = []
    for v in (150.0, 200.0, 250.0):
        out = fresh(f"sweep_{v:g}")
        res = rkpm.run("taylor_bar", set={**SHORT, "velocity_m_s": v}, end_time=4e-6, out=out, plots=False)
        params = res.summary["parameters"]
        check(params["velocity_m_s"] == v, f"speed {v} taken: {params}")
        mv = params["density_kg_m3"] * np.pi * params["radius_m"] ** 2 * params["height_m"] * v
        t, force = res.history["time_s"], res.history["wall_force_y_N"]
        sets = ElementTree.parse(os.path.join(out, "taylor_bar.pvd")).getroot().findall("./Collection/DataSet")
        worst, impulse, before = 0.0, 0.0, len(failures)
        for d in sets:
            mesh = meshio.read(os.path.join(out, d.get("file")))
            p = axial_momentum(mesh, params["density_kg_m3"], np.ones(len(mesh.cells[0].data), bool))[0]
            upto = t <= float(d.get("timestep")) * (1 + 1e-12)
            impulse = float(np.sum(0.5 * (force[upto][1:] + force[upto][:-1]) * np.diff(t[upto])))
            if d is sets[0]:
                check(abs(p + mv) < 1e-9 * mv, f"{v} m/s: momentum at t = 0 is {p}, expected -m v = {-mv}")
            worst = max(worst, abs(p + mv + impulse) / mv)
        check(worst < 0.01, f"{v} m/s: the momentum differs from -m v less the wall's impulse by {worst:.2e} m v")
        check(-impulse > 0.02 * mv, f"{v} m/s: the wall's impulse {-impulse} is not felt (m v = {mv})")
        print(f"{'ok ' if len(failures) == before else '-- '} {v} m/s: P(0) = -m v = {-mv:.5f} kg m/s; wall impulse "
              f"{-impulse:.5f} ({-impulse / mv:.3f} m v); P - P(0) + J at most {worst:.1e} m v over {len(sets)} "
              "snapshots")
        results.append((v, float(np.max(res.plastic_strain)), float(np.min(res.displacement[:, 1])), -impulse))
    eps = [r[1] for r in results]
    check(eps[0] < eps[1] < eps[2], f"plastic strain grows with speed: {results}")
    far = [r[2] for r in results]
    check(far[0] > far[1] > far[2], f"a faster bar moves further: {results}")
    impulse = [r[3] for r in results]
    check(impulse[0] < impulse[1] < impulse[2], f"a faster bar pushes the wall harder: {results}")


def observer():
    seen = []

    def watch(state):
        seen.append((state.step, state.time_s))
        check(state.positions.shape[1] == 2 and state.stress.shape[1] == 4, "observer's array shapes")
        try:
            state.positions[0, 0] = 1.0
            check(False, "observer's arrays are read-only")
        except ValueError:
            pass
        return len(seen) < 3

    res = rkpm.run("taylor_bar", set=SHORT, end_time=END, out=fresh("observer"), plots=False, observe=watch, every=5)
    check([s for s, _ in seen] == [0, 5, 10], f"observer called at steps {[s for s, _ in seen]}")
    check(not res.completed and res.summary["status"] == "stopped", f"status {res.summary['status']}")
    check(res.summary["steps"] == 10 and res.step == 10, f"stopped at step {res.summary['steps']}")


def errors():
    def raises(kind, call, *words):
        try:
            call()
        except kind as e:
            msg = str(e)
            check(all(w in msg for w in words), f"{kind.__name__} message {msg!r} lacks {words}")
            if kind in (rkpm.CaseError, rkpm.RunError):
                check(isinstance(e, rkpm.Error), f"{kind.__name__} is an rkpm.Error")
            return
        except Exception as e:  # noqa: BLE001
            check(False, f"expected {kind.__name__}, got {type(e).__name__}: {e}")
            return
        check(False, f"expected {kind.__name__}, nothing raised")

    with open(os.path.join(REPO, "cases", "taylor_bar.json")) as f:
        doc = json.load(f)
    doc["bodies"][0]["material"]["youngs_modulus_Pa"] = -1.0
    raises(rkpm.CaseError, lambda: rkpm.run(doc, plots=False, out=fresh("bad_field")), "/bodies/0/material",
           "youngs_modulus_Pa")
    raises(rkpm.CaseError, lambda: rkpm.run("taylor_bar", set={"bogus": 1}, out=fresh("bogus")), "bogus")
    raises(rkpm.CaseError, lambda: rkpm.run("taylor_bar", kernel="gaussian", out=fresh("kernel")), "gaussian")
    raises(rkpm.CaseError, lambda: rkpm.run("no_such_case"), "no_such_case")
    # a bar at 20 km/s inverts within its first steps: the run fails after its set-up
    raises(rkpm.RunError, lambda: rkpm.run("taylor_bar", set={**SHORT, "velocity_m_s": 2e4}, end_time=END,
                                           out=fresh("fails"), plots=False), "step")

    # Ctrl-C while stepping (here sent by the observer at step 5) stops the run after the step
    # under way and raises KeyboardInterrupt; the run's folder says where it stopped
    def interrupt_at_5(state):
        if state.step == 5:
            os.kill(os.getpid(), signal.SIGINT)
        return True
    stopped = fresh("interrupted")
    raises(KeyboardInterrupt, lambda: rkpm.run("taylor_bar", set=SHORT, end_time=END, out=stopped, plots=False,
                                               observe=interrupt_at_5))
    with open(os.path.join(stopped, "summary.json")) as f:
        s = json.load(f)
    check("interrupted" in s.get("error", "") and s["steps"] == 6, f"interrupted run's summary: {s.get('error')}, "
          f"step {s.get('steps')}")

    def bad_observer(state):
        raise ZeroDivisionError("observer broke")
    raises(ZeroDivisionError, lambda: rkpm.run("taylor_bar", set=SHORT, end_time=END, out=fresh("obs_err"),
                                               plots=False, observe=bad_observer), "observer broke")


MODES = {"same-as-cli": same_as_cli, "dict-case": dict_case, "sweep": sweep, "observer": observer,
         "errors": errors}
os.makedirs(WORK, exist_ok=True)
MODES[MODE]()
if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print(f"ok  {MODE}")
