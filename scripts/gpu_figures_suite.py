#!/usr/bin/env python3
"""Writes the suite of scripts/gpu-figures.sh: the figure suites' timing jobs, references at 1 spp.

  scripts/gpu_figures_suite.py FIGURES_DIR OUT.toml [--quick]

A figure suite's timing jobs are those with a paper time: a [[paper]] value in milliseconds
(`unit = "ms"`: frames, passes, iterations, preparation phases). Their cases are copied into one
suite, each with the figure suite's [defaults] folded in (so at the paper's resolution, frames and
iterations), named "<figure suite>.<case>" so that cases of different suites cannot clash, with
the [[paper]] values of those jobs that are not errors (a time, a count, a size: a value with a
unit), their job ids renamed alike. Each case keeps its path class, but its references are
rendered at 1 spp: `gibench run` measures every technique job against a reference, and the
figure suites' (up to 1024 spp) would cost more than the techniques; a frame is timed
before its reference is fetched, so the times do not depend on it, and the errors of this run
mean nothing (the figure suites measure them).

--quick keeps one job, the timing job with the fewest pixels (ties: the first in file order),
measured for one frame: enough to run every step of the script on llvmpipe in seconds.

Prints the selected job ids, one a line, for `gibench run --only`. Bad input: one line on stderr,
exit 2, nothing written.
"""
import math
import pathlib
import sys
import tomllib

import toml_writer

QUICK_FRAMES = 1
# Every technique job is measured against a reference; at 1 spp it costs a fraction of a frame.
REFERENCE_SPP = 1
# The cheapest metric (a mean luminance ratio): errors are not what this suite is for.
METRICS = ["energy"]
# [defaults] keys a case inherits (docs/harness.md, "The suite format").
SETTING_KEYS = ("width", "height", "metrics", "frames", "warmup", "repeats")


class InputError(Exception):
    pass


def case_name(case):
    """A case's name as `gibench run` gives it: its own, else "<scene>-<technique>"."""
    if "name" in case:
        return case["name"]
    scene = case["scene"]
    return f"{pathlib.Path(scene).stem if scene.endswith('.toml') else scene}-{case['technique']}"


def job_case(job_id):
    return job_id.split("/", 1)[0]


def timing_jobs(suite):
    """The suite's job ids with a paper time, in the order of their first [[paper]] value."""
    return list(dict.fromkeys(p["job"] for p in suite.get("paper", []) if p.get("unit") == "ms"))


def merged_case(suite_path, suite, case, quick):
    """The case as it runs in its figure suite, under this suite's name, references and metrics."""
    defaults = suite.get("defaults", {})
    merged = {"name": f"{suite['name']}.{case_name(case)}"}
    for key, value in case.items():
        if key == "name":
            continue
        if key == "scene" and value.endswith(".toml"):
            value = str((suite_path.parent / value).resolve())  # relative to its own suite
        merged[key] = value
    for key in SETTING_KEYS:
        if key not in merged and key in defaults:
            merged[key] = defaults[key]
    merged["reference"] = {**defaults.get("reference", {}), **case.get("reference", {}),
                           "spp": REFERENCE_SPP}
    merged["metrics"] = METRICS
    if quick:
        merged["frames"] = QUICK_FRAMES
    return merged


def pixels(suite, case):
    settings = {**suite.get("defaults", {}), **case}
    return settings.get("width", math.inf) * settings.get("height", 1)


def collect(figures_dir):
    """[(path, suite, job ids)] of every figure suite with timing jobs, in file-name order."""
    found = []
    for path in sorted(figures_dir.glob("*.toml")):
        try:
            with open(path, "rb") as f:
                suite = tomllib.load(f)
        except (OSError, tomllib.TOMLDecodeError) as e:
            raise InputError(f"{path}: {e}; fix the suite (gibench run reports it by line)")
        jobs = timing_jobs(suite)
        if jobs:
            found.append((path, suite, jobs))
    if not found:
        raise InputError(f"{figures_dir}: no figure suite has a [[paper]] time (unit \"ms\"); "
                         "give the suites/figures folder")
    return found


def select(found, quick):
    """(cases, papers, job ids) of the new suite."""
    chosen = [(path, suite, job) for path, suite, jobs in found for job in jobs]
    if quick:
        def size(entry):
            path, suite, job = entry
            case = next(c for c in suite["case"] if case_name(c) == job_case(job))
            return pixels(suite, case)
        chosen = [min(chosen, key=size)]
    cases, papers, job_ids = [], [], []
    for path, suite, job in chosen:
        prefix = suite["name"] + "."
        case = next((c for c in suite.get("case", []) if case_name(c) == job_case(job)), None)
        if case is None:
            raise InputError(f"{path}: [[paper]] job '{job}' names no case of the suite; "
                             "fix its job id (gibench run --list shows them)")
        merged = merged_case(path, suite, case, quick)
        if merged not in cases:
            cases.append(merged)
        job_ids.append(prefix + job)
        papers += [{**p, "job": prefix + job} for p in suite["paper"]
                   if p["job"] == job and p.get("unit")]
    return cases, papers, job_ids


def write_suite(out, cases, papers, quick):
    suite = {
        "name": "gpu-figures-quick" if quick else "gpu-figures",
        "description": "The figure suites' timing jobs at the papers' settings, for "
                       "scripts/gpu-figures.sh",
        "case": cases,
        "paper": papers,
    }
    header = ["# Generated by scripts/gpu_figures_suite.py from suites/figures/*.toml: the figure",
              "# suites' timing jobs, their references at 1 spp (errors are meaningless here)."]
    try:
        lines = toml_writer.table_lines("", suite, header)
    except ValueError as e:
        raise InputError(str(e))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")


def main(argv):
    args = [a for a in argv[1:] if a != "--quick"]
    quick = len(args) != len(argv) - 1
    if len(args) != 2 or any(a.startswith("-") for a in args):
        raise InputError("usage: gpu_figures_suite.py FIGURES_DIR OUT.toml [--quick]; "
                         "give the figure suites' folder and the suite file to write")
    figures_dir, out = pathlib.Path(args[0]), pathlib.Path(args[1])
    if not figures_dir.is_dir():
        raise InputError(f"{figures_dir}: not a folder; give suites/figures")
    cases, papers, job_ids = select(collect(figures_dir), quick)
    write_suite(out, cases, papers, quick)
    print("\n".join(job_ids))


if __name__ == "__main__":
    try:
        main(sys.argv)
    except InputError as e:
        print(f"gpu_figures_suite.py: {e}", file=sys.stderr)
        sys.exit(2)
