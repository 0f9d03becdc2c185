#!/usr/bin/env python3
"""scripts/compare-suite-metrics.py's comparison on planted results: identical runs compare
identical and count their metric values; a metric's last digit, a member removed, a job missing
and a reordered job list are each reported; what it ignores (timings, the program's identity)
is not."""
import copy
import importlib.util
import json
import os
import sys

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
spec = importlib.util.spec_from_file_location(
    "compare_suite_metrics", os.path.join(SCRIPTS, "compare-suite-metrics.py"))
compare = importlib.util.module_from_spec(spec)
spec.loader.exec_module(compare)

RESULTS = """{"run": {"id": "r1", "gibench_version": "1.0", "suite_hash": "abc"},
 "jobs": [
  {"id": "cornell-direct", "metrics": {"relmse": 0.0123456789012345, "ssim": 0.875},
   "timings": {"frame_ms": 3.25}, "statistics": {"vertices": 36}},
  {"id": "cornell-reference", "metrics": {"relmse": 0.001}, "timings": {"frame_ms": 9.0}}
 ]}"""


def load(text):
    return json.loads(text, parse_float=compare.Number, parse_int=compare.Number)


def differences(before, after):
    comparison = compare.Comparison()
    jobs, _, schema_lines = compare.compare_suite("planted", before, after, comparison)
    return jobs, comparison, schema_lines


failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


base = load(RESULTS)
jobs, same, schema_lines = differences(base, copy.deepcopy(base))
check(jobs == 2 and not same.differences and not schema_lines, "identical runs differ")
check(same.metric_values == 3, f"counted {same.metric_values} metric values, not 3")

changed = load(RESULTS.replace("0.0123456789012345", "0.0123456789012346"))
_, c, _ = differences(base, changed)
check([d[1] for d in c.differences] == ["metrics.relmse"], f"a last digit: {c.differences}")

ignored = load(RESULTS.replace('"frame_ms": 3.25', '"frame_ms": 4.5').replace('"1.0"', '"1.1"'))
_, c, _ = differences(base, ignored)
check(not c.differences, f"a timing or the version was compared: {c.differences}")

removed = load(RESULTS)
del removed["jobs"][0]["statistics"]
_, c, schema_lines = differences(base, removed)
check(("cornell-direct", "statistics", "present", "absent") in c.differences,
      f"a removed member: {c.differences}")
check(any(line[0].startswith("jobs[].statistics") for line in schema_lines),
      f"a removed member's schema path: {schema_lines}")

missing = load(RESULTS)
missing["jobs"].pop()
_, c, _ = differences(base, missing)
check(("cornell-reference", "(job)", "present", "absent") in c.differences,
      f"a missing job: {c.differences}")

reordered = load(RESULTS)
reordered["jobs"].reverse()
_, c, _ = differences(base, reordered)
check(any(d[1] == "jobs[0]" for d in c.differences), f"a reordered job list: {c.differences}")

# The suites it writes read back as what was written (scripts/toml_writer.py).
import tomllib  # noqa: E402
import toml_writer  # noqa: E402
suite = {"name": "s", "defaults": {"width": 32, "reference": {"spp": 64, "seed": 0}},
         "case": [{"scene": "cornell", "technique": "direct",
                   "set": {"shadow": ["hard", "pcf"], "light_samples": 4}, "reference": {"spp": 8}},
                  {"name": "a \"quoted\" case", "scene": "cloud", "technique": "direct"}],
         "paper": [{"job": "cornell-direct", "quantity": "frame", "value": 1.5e-3}]}
text = "\n".join(toml_writer.table_lines("", suite, []))
check(tomllib.loads(text) == suite, f"TOML does not read back:\n{text}")
try:
    toml_writer.value(float("nan"))
    check(False, "a NaN was written as TOML")
except ValueError:
    pass

for failure in failures:
    print(f"FAIL {failure}")
print("compare-suite-metrics: " + ("ok" if not failures else f"{len(failures)} failed"))
sys.exit(1 if failures else 0)
