"""Independent check of a JSON file written by tests/unit/io/json.cpp, with Python's json module.

Usage: /usr/bin/python3 check_json.py FILE. Exit 0 if every check passes, else prints why, exit 1.
"""
import json
import sys


def reject_constant(name):
    raise ValueError(f"non-standard JSON constant {name} (NaN/Infinity must be written as null)")


def main(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    doc = json.loads(text, object_pairs_hook=lambda pairs: pairs, parse_constant=reject_constant)
    keys = [k for k, _ in doc]
    expected_keys = ["case", "numbers", "hex", "nonfinite", "flags", "order", "empty_array", "empty_object"]
    assert keys == expected_keys, f"top-level keys {keys} != {expected_keys}"
    d = dict(doc)
    expected_case = 'taylor "bar"\n\ttab\\ \x01\x1f/ \u00e9 \u2603'
    assert d["case"] == expected_case, f"string {d['case']!r} != {expected_case!r}"
    numbers, hexes = d["numbers"], d["hex"]
    assert len(numbers) == len(hexes) and len(numbers) > 100, "numbers/hex length mismatch"
    for i, (x, h) in enumerate(zip(numbers, hexes)):
        want = float.fromhex(h)
        assert isinstance(x, (int, float)), f"numbers[{i}] is {type(x)}"
        got = float(x)
        assert got == want and str(got)[0] == str(want)[0], f"numbers[{i}] = {got!r} != {want!r} ({h})"
    assert d["nonfinite"] == [None, None, None], f"nonfinite = {d['nonfinite']}"
    assert d["flags"] == [("ok", True), ("bad", False), ("none", None)], f"flags = {d['flags']}"
    assert [k for k, _ in d["order"]] == ["z", "a", "m"], f"order = {d['order']}"
    assert [v for _, v in d["order"]] == [1, 2, 3], f"order values = {d['order']}"
    assert d["empty_array"] == [] and d["empty_object"] == [], "empty containers"
    print("json ok:", len(numbers), "numbers")


if __name__ == "__main__":
    try:
        main(sys.argv[1])
    except Exception as e:  # report every failure the same way to the doctest
        print("json check failed:", type(e).__name__, e)
        sys.exit(1)
