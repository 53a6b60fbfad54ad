"""What the runner's check scripts share (check_restart.py, check_case_files.py): a check that
records its failure instead of stopping, running rkpm_run, reading a run's summary.json, and
the exit status."""
import json
import os
import subprocess

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message)


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300)


def read(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def summary(folder):
    return json.loads(read(os.path.join(folder, "summary.json")))


def exit_status():
    """0 if every check passed, else 1 after saying how many failed."""
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0
