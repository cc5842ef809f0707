#!/usr/bin/env python3
"""Compares two summary.json files of the same model: every key and value
must agree (numbers to a relative 1e-9), but for what differs between two
runs of one model by nature (wall times, memory, the run's name). Exit 1 with
the first difference otherwise."""
import json
import math
import sys

RUN_SPECIFIC = {"timings", "memory_MB", "memory_at_start_MB",
                "memory_per_dof_kB", "run", "wall_time_per_step",
                "clip_seconds"}


def compare(a, b, path):
    if isinstance(a, dict) and isinstance(b, dict):
        keys_a = set(a) - RUN_SPECIFIC
        keys_b = set(b) - RUN_SPECIFIC
        if keys_a != keys_b:
            return f"{path}: keys differ: {sorted(keys_a ^ keys_b)}"
        for key in sorted(keys_a):
            problem = compare(a[key], b[key], f"{path}/{key}")
            if problem:
                return problem
        return None
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return f"{path}: lengths {len(a)} and {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            problem = compare(x, y, f"{path}[{i}]")
            if problem:
                return problem
        return None
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) \
            and not isinstance(a, bool) and not isinstance(b, bool):
        if not math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-14):
            return f"{path}: {a} and {b}"
        return None
    return None if a == b else f"{path}: {a!r} and {b!r}"


with open(sys.argv[1]) as first, open(sys.argv[2]) as second:
    problem = compare(json.load(first), json.load(second), "")
if problem:
    print("summary.json differs at", problem)
    sys.exit(1)
print("the run's own parameters.prm reproduces summary.json")
