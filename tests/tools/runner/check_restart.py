#!/usr/bin/python3
"""Checkpoints and restarts of rkpm_run, run by ctest (tests/tools/runner.cmake) at one thread.

    check_restart.py same RKPM_RUN WORK_DIR   a run restarted from its mid-run checkpoint into a new folder
                                               gives the uninterrupted run's results, history and last
                                               snapshot bit for bit: Taylor bar (axisymmetric, frictionless
                                               wall) and block forging (plane strain, moving tools, friction)
    check_restart.py kill RKPM_RUN WORK_DIR   a run killed with SIGKILL after a checkpoint continues from its
                                               folder (--restart FOLDER) to the uninterrupted run's outputs;
                                               one stopped by Ctrl-C (SIGINT) checkpoints its last step
    check_restart.py refused RKPM_RUN WORK_DIR restarts that cannot continue are refused in one line; a
                                               damaged checkpoint with the folder's earlier one to restart from

The reference is always the same program's uninterrupted run of the same request: a restart must
not change a run, so equality (not closeness) is the property.
"""
import os
import shutil
import signal
import subprocess
import sys
import time

from checks import check, exit_status, read, run, summary


def checkpoints(folder):
    return sorted(f for f in os.listdir(folder) if f.startswith("checkpoint_") and f.endswith(".rkpmcp"))


def pvd_entries(folder, case):
    text = read(os.path.join(folder, case + ".pvd"))
    return [line.split('timestep="')[1].split('"')[0] for line in text.splitlines() if "<DataSet" in line]


def same_run(reference, other, case, label):
    """The outputs that must not depend on where the run was interrupted."""
    a, b = summary(reference), summary(other)
    for key in ["results", "energy", "steps", "dt_min_s", "dt_max_s", "end_time_s", "particles", "parameters"]:
        check(a[key] == b[key], f"{label}: summary '{key}' differs: {a[key]} vs {b[key]}")
    check(b["status"] == "completed", f"{label}: status {b['status']}")
    check(read(os.path.join(reference, "history.csv")) == read(os.path.join(other, "history.csv")),
          f"{label}: history.csv differs from the uninterrupted run's")
    check(pvd_entries(reference, case) == pvd_entries(other, case), f"{label}: the .pvd snapshot times differ")
    last = sorted(f for f in os.listdir(reference) if f.endswith(".vtu"))[-1]
    check(read(os.path.join(reference, last), "rb") == read(os.path.join(other, last), "rb"),
          f"{label}: the last snapshot {last} differs")


def same(rkpm_run, work):
    requests = [
        ("taylor_bar", ["--set", "radial_particles=6", "--set", "axial_particles=16"], 20e-6),
        ("block_forging", ["--set", "particles_per_side=9", "--set", "friction=0.3"], 2e-4),
    ]
    for case, args, end in requests:
        full, cont = os.path.join(work, case + "-full"), os.path.join(work, case + "-cont")
        for d in (full, cont):
            shutil.rmtree(d, ignore_errors=True)
        base = [rkpm_run, case] + args + ["--end-time", repr(end), "--no-plots", "--quiet"]
        r = run(base + ["--checkpoint-interval", repr(end / 2), "--out", full])
        check(r.returncode == 0, f"{case}: the run failed: {r.stderr}")
        ck = checkpoints(full)
        s = summary(full)
        check(len(ck) == 2, f"{case}: expected a mid-run and an end checkpoint, found {ck}")
        check(ck[-1] == f"checkpoint_{s['steps']:010d}.rkpmcp" and s["last_checkpoint"] == ck[-1],
              f"{case}: the end checkpoint is not named by the last step {s['steps']}: {ck}")
        r = run([rkpm_run, case, "--restart", os.path.join(full, ck[0]), "--out", cont, "--no-plots", "--quiet"])
        check(r.returncode == 0, f"{case}: the restart failed: {r.stderr}")
        same_run(full, cont, case, f"{case} restarted from {ck[0]}")
        restarts = summary(cont).get("restarts", [])
        check(len(restarts) == 1 and 0 < restarts[0]["step"] < s["steps"], f"{case}: restarts recorded {restarts}")
        # Earlier snapshots stay in the first folder; the new .pvd points at them.
        first = [l for l in read(os.path.join(cont, case + ".pvd")).splitlines() if "<DataSet" in l][0]
        target = first.split('file="')[1].split('"')[0]
        check(os.path.exists(os.path.join(cont, target)), f"{case}: the continued .pvd's first file {target} is missing")
        print(f"ok  {case}: restarted at step {restarts[0]['step'] if restarts else '?'} of {s['steps']}, same results")


def kill(rkpm_run, work):
    case, end, interval = "taylor_bar", 30e-6, 2e-6
    reference, killed = os.path.join(work, "kill-reference"), os.path.join(work, "kill-run")
    for d in (reference, killed):
        shutil.rmtree(d, ignore_errors=True)
    base = [rkpm_run, case, "--end-time", repr(end), "--checkpoint-interval", repr(interval), "--no-plots", "--quiet"]
    r = run(base + ["--out", reference])
    check(r.returncode == 0, f"reference run failed: {r.stderr}")
    p = subprocess.Popen(base + ["--out", killed], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.time() + 120
    while time.time() < deadline and p.poll() is None and len(checkpoints(killed) if os.path.isdir(killed) else []) < 2:
        time.sleep(0.005)
    p.send_signal(signal.SIGKILL)
    p.wait()
    ck = checkpoints(killed)
    check(p.returncode == -signal.SIGKILL, f"the run was not killed (exit {p.returncode}): it finished first")
    check(len(ck) >= 1 and summary(killed)["status"] == "running", f"killed run: checkpoints {ck}")
    r = run([rkpm_run, case, "--restart", killed, "--no-plots", "--quiet"])
    check(r.returncode == 0, f"the restart of the killed run failed: {r.stderr}")
    same_run(reference, killed, case, "killed and restarted in place")
    check(checkpoints(killed) == checkpoints(reference), "the restarted folder's checkpoints are not the reference's")
    print(f"ok  killed after {ck[-1] if ck else 'none'}, continued in place to the same results")

    # Ctrl-C stops between two steps with a checkpoint of the last step, and says how to continue.
    interrupted = os.path.join(work, "interrupted-run")
    shutil.rmtree(interrupted, ignore_errors=True)
    p = subprocess.Popen(base + ["--out", interrupted], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    while time.time() < deadline and p.poll() is None and len(
            checkpoints(interrupted) if os.path.isdir(interrupted) else []) < 1:
        time.sleep(0.005)
    p.send_signal(signal.SIGINT)
    err = p.communicate()[1]
    s = summary(interrupted)
    check(p.returncode == 1 and "interrupted by signal 2" in err and "--restart" in err,
          f"Ctrl-C: exit {p.returncode}, {err!r}")
    check(s["status"] == "failed" and f"checkpoint_{s['steps']:010d}.rkpmcp" in checkpoints(interrupted),
          f"Ctrl-C: no checkpoint of the last step {s['steps']}: {checkpoints(interrupted)}")
    r = run([rkpm_run, case, "--restart", interrupted, "--no-plots", "--quiet"])
    check(r.returncode == 0, f"the restart of the interrupted run failed: {r.stderr}")
    same_run(reference, interrupted, case, "interrupted and restarted in place")
    print(f"ok  Ctrl-C at step {s['steps']}, continued in place to the same results")


def refused(rkpm_run, work):
    folder = os.path.join(work, "refused")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(os.path.join(folder, "empty"))
    r = run([rkpm_run, "taylor_bar", "--set", "radial_particles=5", "--set", "axial_particles=9", "--end-time", "4e-6",
             "--checkpoint-interval", "2e-6", "--out", os.path.join(folder, "run"), "--no-plots", "--quiet"])
    check(r.returncode == 0, f"set-up run failed: {r.stderr}")
    ck = [os.path.join(folder, "run", c) for c in checkpoints(os.path.join(folder, "run"))]
    check(len(ck) == 2, f"set-up run: expected a mid-run and an end checkpoint, found {ck}")
    truncated = os.path.join(folder, "truncated.rkpmcp")
    data = read(ck[0], "rb")
    with open(truncated, "wb") as f:
        f.write(data[: len(data) // 2])
    # A run folder whose latest checkpoint has one bit flipped: refused, naming the earlier one;
    # a damaged checkpoint alone in its folder: refused without one to name.
    damaged, alone = os.path.join(folder, "damaged"), os.path.join(folder, "alone")
    for d, files in ((damaged, ck), (alone, ck[:1])):
        os.makedirs(d)
        for c in files:
            shutil.copy(c, d)
        latest = os.path.join(d, os.path.basename(files[-1]))
        data = bytearray(read(latest, "rb"))
        data[len(data) // 2] ^= 0x10
        with open(latest, "wb") as f:
            f.write(data)
    earlier = os.path.join(damaged, os.path.basename(ck[-2]))
    cases = [
        (["taylor_bar", "--restart", damaged],
         [os.path.basename(ck[-1]), "fails its checksum", "the file is damaged; restart from an earlier checkpoint: " + earlier]),
        (["taylor_bar", "--restart", alone], ["fails its checksum", "the file is damaged; restart from an earlier checkpoint"]),
        (["taylor_bar", "--restart", os.path.join(folder, "nosuch")], ["no such checkpoint"]),
        (["taylor_bar", "--restart", os.path.join(folder, "empty")], ["no checkpoint", "--checkpoint-interval"]),
        (["block_forging", "--restart", ck[0]], ["taylor_bar run", "rkpm_run taylor_bar"]),
        (["taylor_bar", "--restart", ck[0], "--kernel", "quartic"], ["cubic", "drop --kernel"]),
        (["taylor_bar", "--restart", ck[0], "--resolution", "2"], ["resolution 1", "drop --resolution"]),
        (["taylor_bar", "--restart", ck[0], "--set", "friction=0.1"], ["--set friction=0.1", "--end-time"]),
        (["taylor_bar", "--restart", truncated], ["truncated"]),
        (["taylor_bar", "--restart", ck[-1]], ["end time already", "--end-time"]),
    ]
    for args, words in cases:
        r = run([rkpm_run] + args + ["--out", os.path.join(folder, "out"), "--no-plots", "--quiet"])
        err = r.stderr.rstrip("\n")
        label = " ".join(a.replace(folder, "...") for a in args)
        check(r.returncode != 0, f"'{label}': exit status {r.returncode}, expected non-zero")
        check(err.count("\n") == 0 and err.startswith("rkpm_run: "), f"'{label}': expected a one-line error: {err!r}")
        for w in words:
            check(w in err, f"'{label}': the error does not say {w!r}: {err!r}")
        if alone in args:
            check(err.endswith("restart from an earlier checkpoint"), f"'{label}': names an earlier checkpoint: {err!r}")
        print(f"ok  {label!r:60} -> {err}")
    # A later end time continues the finished run.
    r = run([rkpm_run, "taylor_bar", "--restart", ck[-1], "--end-time", "6e-6", "--out", os.path.join(folder, "later"),
             "--no-plots", "--quiet"])
    check(r.returncode == 0 and abs(summary(os.path.join(folder, "later"))["end_time_s"] - 6e-6) < 1e-18,
          f"continuing to a later end time failed: {r.stderr}")


def main(argv):
    mode, rkpm_run, work = argv[1], argv[2], argv[3]
    os.makedirs(work, exist_ok=True)
    {"same": same, "kill": kill, "refused": refused}[mode](rkpm_run, work)
    return exit_status()


if __name__ == "__main__":
    sys.exit(main(sys.argv))
