#!/usr/bin/env python3
"""Checks that a change leaves every shipped suite's results unchanged (docs/harness.md, "Checking
a refactoring leaves results unchanged"): runs a shrunk copy of each suite with a build from
before the change and one from after it, and compares the two results.json files value by value.

  scripts/compare-suite-metrics.py --before GIBENCH --after GIBENCH --work DIR
      [--suites GLOB ...] [--jobs N] [--side before|after|both|none]

Shrinking: every case, technique parameter, iteration count and checkpoint of suites/*.toml and
suites/figures/*.toml is kept; images are at most --size pixels a side, references at most --spp
samples (a reference case's spp checkpoints scaled with its spp), technique jobs at most --frames
measured and --warmup warm-up frames; the few settings in CAPS that would still take minutes a
job are capped, and every cap is printed and written to DIR/shrink.txt. The shrunk suites are
written once, to DIR/suites, and both sides run those same files.

Runs: `gibench run DIR/suites/<suite>.toml --out DIR/<side>/<suite> --store DIR/store-<side>
--no-history --jobs N`, output in DIR/<side>/<suite>.log, the time per suite in
DIR/<side>/times.json. A side already run (its results.json exists) is not run again.
--side before runs the before side alone (nothing compared), after runs the after side and
compares, both runs both and compares, none compares what is there.

Comparison: every job's metric values (metrics, metrics_full, the convergence points' metrics and
fit) and every other value of results.json except those in IGNORED (timings, dates, versions,
the host and the store), numbers bit for bit; and the schema: every member path (array indices
left out) with its JSON type. Prints every difference; exits 1 on any (or on a failed run), 0
when there is none, 2 on bad input.
"""
import argparse
import fnmatch
import json
import os
import re
import struct
import subprocess
import sys
import time
import tomllib

import toml_writer

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SUITE_DIRS = ("suites", os.path.join("suites", "figures"))
SIDES = ("before", "after")

# Settings that would still take minutes a job at the shrunk sizes, and the largest value the
# shrunk suites give them: (technique, scene or "*", setting, cap), the setting a technique
# parameter or "size" (the image's width and height). A case that sweeps the parameter keeps its
# values: they name its jobs, which the suite's figures and paper values cite. One that sets a
# larger value, or leaves it to its default (larger than each cap here), gets the cap.
CAPS = (
    # Preprocessing renders a shadow cube map per virtual light (about four per entry point) and
    # gathers them into every cluster's pane: ~100 s a chamber job at the defaults on llvmpipe.
    ("light_path_map", "*", "entry_points", 1024),
    ("light_path_map", "*", "vpl_shadow_map_size", 16),
    ("light_path_map", "*", "atlas", 128),
    # Each of the furnace's 512 area lights is rasterised from every pixel: ~170 s at 16².
    ("jittered_light_sampling", "furnace", "size", 8),
)

# Values that differ between two builds or two runs without the results changing: times and
# what they depend on, the program's and the machine's identity, where the run put its files.
# Glob patterns over member paths ("jobs[].reference.spp": array indices written as []).
IGNORED = (
    "run.id", "run.started", "run.finished", "run.gibench_version", "run.git_commit",
    "run.git_dirty", "run.build_type", "run.host", "run.cpu", "run.cpu_cores",
    "run.embree_version", "run.gl_*", "run.store", "run.conditions",
    "run.suite_file",  # the path given; suite_hash is its content
    "jobs[].timings", "jobs[].iteration_timings", "jobs[].repeats", "jobs[].upload_ms",
    "jobs[].prepare_ms", "jobs[].iterate_ms", "jobs[].seconds", "jobs[].conditions",
    "jobs[].execution",
    "jobs[].job_hash",  # hashes the program version
    "jobs[].*reference.render_seconds", "jobs[].*reference.store_hit",
    # A store key hashes the reference renderer's sources, comments included (see
    # reference/reference_store.h), and names the copies of the references; what defines a
    # reference (scene hash, size, spp, seed, path class, pixel sampling) is compared field by
    # field.
    "jobs[].*reference.key", "jobs[].outputs.reference_viewer_data",
    "jobs[].outputs.*reference_exr",
    "jobs[].convergence.points[].seconds", "jobs[].statistics.*_ms",
    "jobs[].statistics.*_per_second",  # the irradiance caches' records_per_second
)

# Member paths whose values are metric values, counted apart from the other values.
METRIC_VALUES = (
    "jobs[].metrics.*", "jobs[].metrics_full.*", "jobs[].convergence.points[].metrics.*",
    "jobs[].convergence.fit_*",
)


def fail_input(message):
    print(f"compare-suite-metrics: {message}", file=sys.stderr)
    sys.exit(2)


def say(message):
    print(message, flush=True)


# --- Shrinking ---------------------------------------------------------------------------------

def shipped_suites(patterns):
    """(name, path) of every shipped suite whose name matches one of the patterns."""
    found = []
    for directory in SUITE_DIRS:
        for entry in sorted(os.listdir(os.path.join(REPO, directory))):
            if entry.endswith(".toml"):
                found.append((entry[:-len(".toml")], os.path.join(REPO, directory, entry)))
    names = [name for name, _ in found]
    for name in set(names):
        if names.count(name) > 1:
            fail_input(f"two shipped suites are named {name}; rename one")
    for pattern in patterns:
        if not any(fnmatch.fnmatchcase(name, pattern) for name in names):
            fail_input(f"--suites {pattern} matches no suite; the suites are {', '.join(names)}")
    return [(name, path) for name, path in found
            if any(fnmatch.fnmatchcase(name, pattern) for pattern in patterns)]


def not_self_contained(suite):
    """Why the suite cannot run from another folder, or None: a scene file is found relative to
    the suite file."""
    for case in suite.get("case", []):
        if case.get("scene", "").endswith(".toml"):
            return f"case {case.get('name', case['scene'])} reads the scene file {case['scene']}"
    return None


def apply_cap(case, defaults, setting, limit):
    """Caps one setting of a case; returns what it did, or None when the case is within it."""
    if setting == "size":
        width, height = (case.get(k, defaults.get(k)) for k in ("width", "height"))
        if width is not None and max(width, height) <= limit:
            return None
        case["width"], case["height"] = min(width or limit, limit), min(height or limit, limit)
        return f"image {width}x{height} -> {case['width']}x{case['height']}"
    settings = case.setdefault("set", {})
    value = settings.get(setting)
    if isinstance(value, list):
        return f"{setting} swept over {value}: kept" if max(map(float, value)) > limit else None
    if value is not None and float(value) <= limit:
        return None
    settings[setting] = limit
    return f"{setting} {'default' if value is None else value} -> {limit}"


def scaled_checkpoints(checkpoints, old_spp, new_spp):
    """A reference case's checkpoints are spp counts up to its spp: scaled with it, the same
    number of them where the new spp leaves room."""
    scaled = []
    for checkpoint in checkpoints:
        value = max(1, checkpoint * new_spp // old_spp)
        if not scaled or value > scaled[-1]:
            scaled.append(value)
    return scaled


def shrink_suite(suite, limits):
    """Shrinks the parsed suite in place; returns what the caps (CAPS) did to its cases."""
    notes = []
    defaults = suite.setdefault("defaults", {})
    default_spp = defaults.get("reference", {}).get("spp", 1024)  # suites/suite.h's default
    for case in suite["case"]:
        if case["technique"] == "reference" and "checkpoints" in case:
            spp = case.get("reference", {}).get("spp", default_spp)
            case["checkpoints"] = scaled_checkpoints(case["checkpoints"], spp,
                                                     min(spp, limits.spp))
    for table in [defaults] + suite["case"]:
        for key in ("width", "height"):
            if key in table:
                table[key] = min(table[key], limits.size)
        if "frames" in table:
            table["frames"] = min(table["frames"], limits.frames)
        if "warmup" in table:
            table["warmup"] = min(table["warmup"], limits.warmup)
        if "spp" in table.get("reference", {}):
            table["reference"]["spp"] = min(table["reference"]["spp"], limits.spp)
    for case in suite["case"]:
        where = case.get("name", f"{case['scene']}-{case['technique']}")
        for technique, scene, setting, limit in CAPS:
            if case["technique"] == technique and scene in ("*", case["scene"]):
                note = apply_cap(case, defaults, setting, limit)
                if note:
                    notes.append(f"{where}: {note}")
    return notes


def limits_line(limits):
    return (f"size <= {limits.size}, reference spp <= {limits.spp}, frames <= {limits.frames}, "
            f"warmup <= {limits.warmup}")


def shrunk_suites(suites, limits):
    """The shrunk copies' text: [(name, text, cap notes)], and the suites skipped with why."""
    shrunk, skipped = [], []
    for name, path in suites:
        with open(path, "rb") as f:
            suite = tomllib.load(f)
        reason = not_self_contained(suite)
        if reason:
            skipped.append((name, reason))
            continue
        notes = [f"{name}: {note}" for note in shrink_suite(suite, limits)]
        lines = [f"# {os.path.relpath(path, REPO)} shrunk by scripts/compare-suite-metrics.py",
                 f"# {limits_line(limits)}"]
        toml_writer.table_lines("", suite, lines)
        shrunk.append((name, "\n".join(lines) + "\n", notes))
    return shrunk, skipped


def check_earlier_shrink(work, limits):
    """A work folder holds runs of one shrink: both sides must run the same files."""
    path = os.path.join(work, "shrink.txt")
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            earlier = f.readline().strip()
        if earlier != limits_line(limits):
            fail_input(f"{work} holds runs shrunk to {earlier}, not {limits_line(limits)}; give "
                       "the same --size, --spp, --frames and --warmup, or another --work")


def write_shrunk_suites(shrunk, work, limits):
    """Writes the shrunk copies not written yet (an earlier side's copy is kept, so that both
    sides run the same file); returns [(name, path)]."""
    directory = os.path.join(work, "suites")
    os.makedirs(directory, exist_ok=True)
    paths = []
    for name, text, _ in shrunk:
        target = os.path.join(directory, name + ".toml")
        if not os.path.exists(target):
            with open(target + ".tmp", "w", encoding="utf-8") as f:
                f.write(text)
            os.replace(target + ".tmp", target)
        else:
            with open(target, encoding="utf-8") as f:
                if f.read() != text:
                    say(f"note: {target} differs from a fresh shrink of the suite (the suite "
                        "changed since it was written); both sides run the file in the work folder")
        paths.append((name, target))
    with open(os.path.join(work, "shrink.txt"), "w", encoding="utf-8") as f:
        f.write(limits_line(limits) + "\n")
        f.writelines(note + "\n" for _, _, notes in shrunk for note in notes)
    return paths


# --- Running -----------------------------------------------------------------------------------

def results_path(work, side, name):
    return os.path.join(work, side, name, "results.json")


def run_side(side, gibench, suites, work, jobs):
    """Runs every suite not run yet on this side; returns the suites whose run failed."""
    times_path = os.path.join(work, side, "times.json")
    times = {}
    if os.path.exists(times_path):
        with open(times_path, encoding="utf-8") as f:
            times = json.load(f)
    failed = []
    for index, (name, suite_file) in enumerate(suites, 1):
        out = os.path.join(work, side, name)
        if os.path.exists(os.path.join(out, "results.json")):
            say(f"[{index}/{len(suites)}] {side} {name}: already run (delete {out} to rerun)")
            continue
        say(f"[{index}/{len(suites)}] {side} {name} ...")
        log = out + ".log"
        command = [gibench, "run", suite_file, "--out", out, "--store",
                   os.path.join(work, "store-" + side), "--no-history", "--jobs", str(jobs)]
        start = time.monotonic()
        with open(log, "w", encoding="utf-8") as f:
            status = subprocess.run(command, stdout=f, stderr=subprocess.STDOUT).returncode
        seconds = time.monotonic() - start
        if not os.path.exists(os.path.join(out, "results.json")):
            say(f"    FAILED (exit {status}) after {seconds:.0f} s: see {log}")
            failed.append(name)
            continue
        # A job the machine could not run is recorded as failed in a complete results.json
        # (exit 1); the comparison shows it.
        with open(os.path.join(out, "results.json"), encoding="utf-8") as f:
            jobs_run = json.load(f)["jobs"]
        times[name] = round(seconds, 1)
        with open(times_path, "w", encoding="utf-8") as f:
            json.dump(times, f, indent=1)
        failures = sum(1 for job in jobs_run if job.get("failure"))
        say(f"    {len(jobs_run)} jobs in {seconds:.0f} s"
            + (f", {failures} of them failed: see {log}" if failures else ""))
    total = sum(times.get(name, 0) for name, _ in suites)
    say(f"{side}: {total:.0f} s over {sum(name in times for name, _ in suites)} suites "
        f"(per suite in {times_path})")
    return failed


# --- Comparing ---------------------------------------------------------------------------------

class Number:
    """A JSON number as written: compared by the bits of the double it reads back to, or, for an
    integer (a 64-bit seed is beyond a double's exact integers), by its digits."""

    def __init__(self, text):
        self.text = text
        integer = text.lstrip("-").isdigit()
        self.identity = text if integer else struct.pack("<d", float(text))

    def __eq__(self, other):
        return isinstance(other, Number) and self.identity == other.identity

    def __str__(self):
        return self.text


def load_results(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_float=Number, parse_int=Number)


def path_pattern(patterns):
    """One regular expression for member path patterns in which only * is special."""
    alternatives = "|".join(re.escape(pattern).replace(r"\*", ".*") for pattern in patterns)
    return re.compile(f"(?:{alternatives})\\Z")


IGNORED_PATHS = path_pattern(IGNORED)
METRIC_PATHS = path_pattern(METRIC_VALUES)


def json_type(value):
    if isinstance(value, Number) or value in ("nan", "inf", "-inf"):
        return "number"  # docs/results-schema.md: non-finite numbers are written as strings
    return {dict: "object", list: "array", str: "string", bool: "boolean",
            type(None): "null"}[type(value)]


def schema(value, path="", out=None):
    """Every member path with array indices left out, with the JSON types found at it."""
    out = {} if out is None else out
    out.setdefault(path, set()).add(json_type(value))
    if isinstance(value, dict):
        for key, member in value.items():
            schema(member, f"{path}.{key}" if path else key, out)
    elif isinstance(value, list):
        for item in value:
            schema(item, path + "[]", out)
    return out


class Comparison:
    def __init__(self):
        self.metric_values = 0
        self.other_values = 0
        self.differences = []  # (job, path, before, after)

    def values(self, job, path, before, after, shown):
        """Compares two values at `path` (indices as []); `shown` is the path with indices, from
        the job."""
        if IGNORED_PATHS.match(path):
            return
        if isinstance(before, dict) and isinstance(after, dict):
            if list(before) != list(after) and set(before) == set(after):
                self.differences.append((job, shown, "members " + ", ".join(before),
                                         "members " + ", ".join(after)))
            for key in list(before) + [key for key in after if key not in before]:
                member = f"{path}.{key}" if path else key
                member_shown = f"{shown}.{key}" if shown else key
                if key not in after:
                    self.differences.append((job, member_shown, "present", "absent"))
                elif key not in before:
                    self.differences.append((job, member_shown, "absent", "present"))
                else:
                    self.values(job, member, before[key], after[key], member_shown)
        elif isinstance(before, list) and isinstance(after, list):
            if len(before) != len(after):
                self.differences.append((job, shown, f"{len(before)} items", f"{len(after)} items"))
            for i, (b, a) in enumerate(zip(before, after)):
                self.values(job, path + "[]", b, a, f"{shown}[{i}]")
        else:
            if METRIC_PATHS.match(path):
                self.metric_values += 1
            else:
                self.other_values += 1
            if before != after or type(before) is not type(after):
                self.differences.append((job, shown, str(before), str(after)))


def compare_suite(name, before, after, comparison):
    """Compares the suite's two results; returns (jobs compared, failed jobs, schema differences:
    (path, types before, types after))."""
    schema_before, schema_after = schema(before), schema(after)
    schema_lines = [(path, " or ".join(sorted(schema_before.get(path, {"absent"}))),
                     " or ".join(sorted(schema_after.get(path, {"absent"}))))
                    for path in sorted(schema_before.keys() | schema_after.keys())
                    if schema_before.get(path) != schema_after.get(path)]
    top_before = {k: v for k, v in before.items() if k != "jobs"}
    top_after = {k: v for k, v in after.items() if k != "jobs"}
    comparison.values("(run)", "", top_before, top_after, "")
    jobs_before = {str(job["id"]): job for job in before["jobs"]}
    jobs_after = {str(job["id"]): job for job in after["jobs"]}
    if list(jobs_before) != list(jobs_after) and set(jobs_before) == set(jobs_after):
        index, first = next((i, pair) for i, pair in enumerate(zip(jobs_before, jobs_after))
                            if pair[0] != pair[1])
        comparison.differences.append(("(run)", f"jobs[{index}]", *first))
    for job_id in jobs_before:
        if job_id not in jobs_after:
            comparison.differences.append((job_id, "(job)", "present", "absent"))
    for job_id in jobs_after:
        if job_id not in jobs_before:
            comparison.differences.append((job_id, "(job)", "absent", "present"))
    compared = [job_id for job_id in jobs_before if job_id in jobs_after]
    for job_id in compared:
        comparison.values(job_id, "jobs[]", jobs_before[job_id], jobs_after[job_id], "")
    failed = [(job_id, str(jobs_before[job_id].get("failure", ""))) for job_id in compared
              if jobs_before[job_id].get("failure", "")]
    return len(compared), failed, schema_lines


def compare(suites, work, failed_runs):
    """Prints the comparison of every suite's two runs; returns whether anything differs."""
    total_jobs, total_metrics, total_other, suites_compared = 0, 0, 0, 0
    differ = bool(failed_runs)
    for name, _ in suites:
        if name in failed_runs:
            say(f"{name}: not compared: the {failed_runs[name]} run failed")
            continue
        comparison = Comparison()
        jobs, failed, schema_lines = compare_suite(
            name, load_results(results_path(work, "before", name)),
            load_results(results_path(work, "after", name)), comparison)
        suites_compared += 1
        total_jobs += jobs
        total_metrics += comparison.metric_values
        total_other += comparison.other_values
        verdict = "identical" if not comparison.differences and not schema_lines else \
            f"different values {len(comparison.differences)}, schema paths {len(schema_lines)}"
        say(f"{name}: {jobs} jobs, {comparison.metric_values} metric values, "
            f"{comparison.other_values} other values: {verdict}")
        for job_id, reason in failed:
            say(f"    note: job {job_id} failed on the before side ({reason}): no metrics")
        for job_id, path, b, a in comparison.differences:
            say(f"    DIFF {name} {job_id} {path}: before {b} after {a}")
        for path, b, a in schema_lines:
            say(f"    DIFF {name} schema {path}: before {b} after {a}")
        differ = differ or bool(comparison.differences or schema_lines)
    say(f"suites compared: {suites_compared} of {len(suites)}; jobs compared: {total_jobs}; "
        f"metric values compared: {total_metrics}; other values compared: {total_other}")
    say("ignored (never compared): " + ", ".join(IGNORED))
    say("RESULT: " + ("DIFFERENCES" if differ else "identical"))
    return differ


# --- Command line ------------------------------------------------------------------------------

def executable(path, flag):
    if not path:
        fail_input(f"{flag} is required for this --side; give the gibench binary")
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        fail_input(f"{flag} {path} is not an executable file; give the gibench binary")
    return os.path.abspath(path)


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--before", help="gibench built before the change")
    parser.add_argument("--after", help="gibench built after the change")
    parser.add_argument("--work", required=True, help="folder of the shrunk suites and the runs")
    parser.add_argument("--suites", nargs="+", default=["*"], metavar="GLOB",
                        help="suite names (file names without .toml) to check (default: all)")
    parser.add_argument("--jobs", type=int, default=1, help="gibench run --jobs (default 1)")
    parser.add_argument("--side", choices=("before", "after", "both", "none"), default="both",
                        help="which runs to make before comparing (before: no comparison)")
    parser.add_argument("--size", type=int, default=32, help="largest image side (default 32)")
    parser.add_argument("--spp", type=int, default=64, help="largest reference spp (default 64)")
    parser.add_argument("--frames", type=int, default=2, help="most measured frames (default 2)")
    parser.add_argument("--warmup", type=int, default=1, help="most warm-up frames (default 1)")
    arguments = parser.parse_args()
    for flag in ("jobs", "size", "spp", "frames"):
        if getattr(arguments, flag) < 1:
            fail_input(f"--{flag} {getattr(arguments, flag)} is below 1; give a positive number")
    if arguments.warmup < 0:
        fail_input(f"--warmup {arguments.warmup} is negative; give 0 or more")
    if os.path.exists(arguments.work) and not os.path.isdir(arguments.work):
        fail_input(f"--work {arguments.work} is a file; give a folder")
    return arguments


def main():
    arguments = parse_arguments()
    work = os.path.abspath(arguments.work)
    sides = {"before": ["before"], "after": ["after"], "both": list(SIDES), "none": []}
    to_run = sides[arguments.side]
    binaries = {side: executable(getattr(arguments, side), f"--{side}") for side in to_run}
    check_earlier_shrink(work, arguments)
    texts, skipped = shrunk_suites(shipped_suites(arguments.suites), arguments)
    if arguments.side in ("after", "none"):
        for side in SIDES[:1] if arguments.side == "after" else SIDES:
            missing = [name for name, _, _ in texts
                       if not os.path.exists(results_path(work, side, name))]
            if missing:
                fail_input(f"no {side} run of {', '.join(missing)} in {work}; run --side {side} "
                           "first")
    os.makedirs(work, exist_ok=True)
    shrunk = write_shrunk_suites(texts, work, arguments)
    say(f"shrunk: {limits_line(arguments)}")
    for name, reason in skipped:
        say(f"skipped {name}: {reason}, and the shrunk copy is in another folder")
    for _, _, notes in texts:
        for note in notes:
            say(f"capped {note}")
    failed_runs = {}
    for side in to_run:
        os.makedirs(os.path.join(work, side), exist_ok=True)
        failed_runs.update({name: side for name in run_side(side, binaries[side], shrunk, work,
                                                             arguments.jobs)})
    if arguments.side == "before":
        sys.exit(1 if failed_runs else 0)
    sys.exit(1 if compare(shrunk, work, failed_runs) else 0)


if __name__ == "__main__":
    main()
