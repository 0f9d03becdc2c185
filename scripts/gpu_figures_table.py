#!/usr/bin/env python3
"""The technique benchmarks of scripts/gpu-figures.sh, and its Markdown table.

  gpu_figures_table.py bench-filter TECHNIQUE...          the benchmarks of these techniques
  gpu_figures_table.py bench-filter --first TECHNIQUE...  < names: the first of each technique
  gpu_figures_table.py renderer BENCH.json                the GL renderer the benchmarks ran on
  gpu_figures_table.py markdown BENCH.json RUN_DIR OUT_DIR TECHNIQUE... [--quick]
                                     [--raycast RAYCAST.json]  with the ray-casting table
                                                          writes OUT_DIR/<renderer>.md, prints it

A technique's benchmarks in gib_realtime_bench are the families BM_<Technique>Frame… (a frame)
and BM_<Technique>Iteration… (one iteration of an iterative technique), <Technique> its catalogue
name in CamelCase (light_path_map: BM_LightPathMapFrame); the label of each ends with the
renderer's GL_RENDERER and the clock (bench/realtime/support/technique_frames.h). The run is
`gibench run` of the suite scripts/gpu_figures_suite.py wrote: its results.json
(docs/results-schema.md) holds the per-pass timings and the papers' values. Bad input: one line
on stderr, exit 2, nothing written.
"""
import json
import pathlib
import re
import sys

KINDS = ("Frame", "Iteration")
ERE_SPECIAL = re.compile(r"([.\[\](){}*+?|^$\\])")


class InputError(Exception):
    pass


def camel(technique):
    return "".join(part.capitalize() for part in technique.split("_"))


def technique_of(benchmark, techniques):
    """(technique, "frame" or "iteration") of a benchmark name, or None for another benchmark."""
    for technique in techniques:
        for kind in KINDS:
            if benchmark.startswith(f"BM_{camel(technique)}{kind}"):
                return technique, kind.lower()
    return None


def bench_filter(techniques):
    return f"^BM_({'|'.join(camel(t) for t in techniques)})({'|'.join(KINDS)})"


def first_of_each(names, techniques):
    """A filter matching exactly the first listed benchmark of each technique."""
    first = {}
    for name in names:
        found = technique_of(name, techniques)
        if found and found[0] not in first:
            first[found[0]] = name
    if not first:
        raise InputError("no benchmark of these techniques was listed; "
                         "check the benchmark program (gib_realtime_bench)")
    return "^(" + "|".join(ERE_SPECIAL.sub(r"\\\1", n) for n in first.values()) + ")$"


def load_json(path, what):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        raise InputError(f"{path}: cannot read {what} ({e}); run the step that writes it again")


def bench_renderer(bench):
    """GL_RENDERER from the benchmarks' labels ("<renderer>, <clock> clock"), which must agree."""
    renderers = {b["label"].rsplit(", ", 1)[0] for b in bench["benchmarks"] if b.get("label")}
    if len(renderers) != 1:
        raise InputError(f"the benchmarks name {len(renderers)} GL renderers "
                         f"({', '.join(sorted(renderers)) or 'none'}); run them on one device")
    return renderers.pop()


def slug(text):
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-") or "renderer"


def number(value):
    """Three significant digits, never in exponent form (times span 0.01 ms to minutes)."""
    if value is None:
        return "—"
    magnitude = abs(value)
    digits = 0 if magnitude >= 100 else 1 if magnitude >= 10 else 2 if magnitude >= 1 else 3
    return f"{value:,.{digits}f}"


def cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cell(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def ms(benchmark):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[benchmark["time_unit"]]
    return benchmark["real_time"] * scale


def technique_rows(bench, techniques):
    rows = []
    for b in bench["benchmarks"]:
        found = technique_of(b["name"], techniques)
        if not found or b.get("run_type", "iteration") != "iteration":
            continue
        technique, kind = found
        case = b["name"].removesuffix("/manual_time").removesuffix("/real_time")
        commands = b.get(f"{kind}_gpu_commands")
        if b.get("error_occurred"):  # skipped (SkipWithError): what this machine lacks
            rows.append([technique, case, f"skipped: {b.get('error_message', '')}", kind, "—", ""])
            continue
        rows.append([technique, case, number(ms(b)), kind,
                     "—" if commands is None else f"{commands:g}",
                     b.get("label", "").rsplit(", ", 1)[-1]])
    missing = [t for t in techniques if t not in {r[0] for r in rows}]
    if missing:
        raise InputError(f"no benchmark of {', '.join(missing)} ran; check the benchmark program "
                         "(each technique needs a BM_<Technique>Frame or …Iteration benchmark)")
    return rows


# A quantity's value as results/quantity.h defines it, for the quantities a paper time uses.
def pass_median(timings, name):
    if not timings:
        return None
    passes = timings["passes"]
    found = next((p for p in passes if p["path"] == name), None) or \
        next((p for p in passes if p["name"] == name), None)
    return found and found["median_ms"]


def term_value(job, term):
    if term.startswith("statistic:"):
        return job.get("statistics", {}).get(term.removeprefix("statistic:"))
    if term == "iterations":
        return job["iterations"] or None
    if term == "iteration" or term.startswith("iteration/"):
        return pass_median(job.get("iteration_timings"), term)
    return pass_median(job.get("timings"), term)


def quantity_value(job, quantity):
    values = [term_value(job, t.strip()) for t in quantity.split("+")]
    return None if any(v is None for v in values) else sum(values)


def paper_rows(results):
    jobs = {j["id"]: j for j in results["jobs"]}
    rows = []
    for p in results["paper"]:
        job = jobs.get(p["job"])
        value = None
        if job is None:
            ours = "not run"
        elif job.get("failure"):
            ours = "failed: " + job["failure"]
        else:
            value = quantity_value(job, p["quantity"])
            ours = number(value)
        ratio = f"{value / p['value']:.2g}×" if value is not None and p["value"] else "—"
        rows.append([p["job"], p["quantity"], ours, number(p["value"]), ratio, p["unit"],
                     p["source"] + (f" ({p['note']})" if p.get("note") else "")])
    return rows


def pass_tables(results):
    text = ""
    for job in results["jobs"]:
        params = ", ".join(f"{k}={v}" for k, v in job.get("scene_parameters", {}).items())
        text += (f"\n### {job['id']}\n\n`{job['technique']}` on {job['scene']}"
                 f"{f' ({params})' if params else ''}, {job['width']}×{job['height']}")
        if job.get("failure"):
            text += f": failed ({job['failure']})\n"
            continue
        timings = [t for t in (job.get("timings"), job.get("iteration_timings")) if t]
        iterations = f"{job['iterations']} iterations, " if job["iterations"] else ""
        text += (f", {timings[0]['measured_frames']} measured frames after "
                 f"{timings[0]['warmup_frames']} warm-up, {iterations}"
                 f"{timings[0]['clock']} clock.\n\n")
        rows = [["&nbsp;&nbsp;" * p["depth"] + p["path"], number(p["median_ms"]),
                 f"{p['calls_per_frame']:g}", "—" if p.get("gpu_commands_per_frame") is None
                 else f"{p['gpu_commands_per_frame']:g}"] for t in timings for p in t["passes"]]
        text += table(["pass", "median ms", "calls", "GPU commands"], rows)
    return text


def raycast_section(raycast):
    """The table of `gibench raycast-bench` (book Ch. 5): M rays/s and mismatches per structure."""
    text = ("\n## Ray casting against Embree (book Ch. 5)\n\n`gibench raycast-bench`: the same "
            "rays cast by Embree on every CPU core and by each GPU structure; mismatches against "
            "Embree under the tie rule (realtime/ray_casting/README.md). The book: 10–20 M rays/s "
            "on 10 000–100 000 triangles.\n\n")
    rows = []
    for case in raycast["cases"]:
        scene = " ".join([case["scene"]] + case["scene_parameters"])
        for s in case["structures"]:
            if "skipped" in s:
                rows.append([scene, case["rays"], f"{case['triangles']:,}", s["name"], "skipped",
                             "—", "—", "—"])
                continue
            rows.append([scene, case["rays"], f"{case['triangles']:,}", s["name"],
                         "—" if s["name"] == "embree" else str(s["mismatches"]),
                         number(s["mrays_per_second"]), number(s["build_ms"]),
                         "—" if s["bytes"] is None else number(s["bytes"] / 1048576)])
    return text + table(["scene", "rays", "triangles", "structure", "mismatches", "M rays/s",
                         "build ms", "MiB"], rows)


def markdown(bench, results, techniques, quick, raycast=None):
    run = results["run"]
    renderer = bench_renderer(bench)
    if run["gl_renderer"] and run["gl_renderer"] != renderer:
        raise InputError(f"the benchmarks ran on '{renderer}' but the suite on "
                         f"'{run['gl_renderer']}'; set GIBENCH_GL_DEVICE to one device and rerun")
    date = run["finished"][:10]
    dirty = ", uncommitted changes" if run["git_dirty"] else ""
    text = f"# GPU figures: {renderer}\n\n"
    text += (f"Written by `scripts/gpu-figures.sh{' --quick' if quick else ''}` on {date}. ")
    if quick:
        text += ("**Quick mode**: one benchmark per technique and one timing job, to test the "
                 "script; not figures to commit. ")
    text += "docs/harness.md, \"GPU figures\", says how it is made and read.\n\n"
    text += table(["", ""], [
        ["GL renderer", renderer], ["GL vendor", run["gl_vendor"]],
        ["GL version", run["gl_version"]], ["GL device", run["gl_device"]],
        ["CPU", f"{run['cpu']} ({run['cpu_cores']} logical cores)"], ["host", run["host"]],
        ["gibench", f"{run['gibench_version']} (commit {run['git_commit']}{dirty}, "
                    f"{run['build_type']})"],
        ["benchmarks run", bench["context"]["date"]],
        ["suite run (UTC)", f"{run['started']} to {run['finished']}"]])
    text += ("\n## Frame time per technique\n\n`gib_realtime_bench`: the mean time of a frame "
             "(or of one iteration) over the benchmark's iterations, after two warm-up frames; "
             "GPU commands are the draws and dispatches per frame.\n\n")
    text += table(["technique", "benchmark", "ms", "per", "GPU commands", "clock"],
                  technique_rows(bench, techniques))
    text += ("\n## The papers' figures beside ours\n\n`gibench run` of the figure suites' timing "
             "jobs (`<figure suite>.<job>`; their cases as in `suites/figures/`): ours is the "
             "median over the measured frames (or iterations) of the quantity the paper reports, "
             "or the technique's statistic. The papers' numbers come from their own hardware.\n\n")
    text += table(["job", "quantity", "ours", "paper", "ours/paper", "unit", "source"],
                  paper_rows(results))
    text += "\n## Per-pass times of the timing jobs\n" + pass_tables(results)
    if raycast is not None:
        text += raycast_section(raycast)
    return renderer, text


def main(argv):
    command, args = (argv[1], argv[2:]) if len(argv) > 1 else ("", [])
    if command == "bench-filter" and args:
        if args[0] == "--first":
            print(first_of_each(sys.stdin.read().split(), args[1:]))
        else:
            print(bench_filter(args))
    elif command == "renderer" and len(args) == 1:
        print(bench_renderer(load_json(args[0], "the benchmarks' JSON")))
    elif command == "markdown" and len(args) >= 4:
        quick = "--quick" in args
        args = [a for a in args if a != "--quick"]
        raycast = None
        if "--raycast" in args:
            at = args.index("--raycast")
            if at + 1 >= len(args):
                raise InputError("--raycast needs the path of raycast.json")
            raycast = load_json(args[at + 1], "the ray-casting bench's JSON")
            del args[at:at + 2]
        bench = load_json(args[0], "the benchmarks' JSON")
        results = load_json(pathlib.Path(args[1]) / "results.json", "the run's results")
        renderer, text = markdown(bench, results, args[3:], quick, raycast)
        out = pathlib.Path(args[2]) / f"{slug(renderer)}.md"
        out.write_text(text, encoding="utf-8")
        print(out)
    else:
        raise InputError("usage: gpu_figures_table.py bench-filter [--first] TECHNIQUE... | "
                         "renderer BENCH.json | markdown BENCH.json RUN_DIR OUT_DIR TECHNIQUE... "
                         "[--quick] [--raycast RAYCAST.json]; see the comment at the top of the "
                         "file")


if __name__ == "__main__":
    try:
        main(sys.argv)
    except InputError as e:
        print(f"gpu_figures_table.py: {e}", file=sys.stderr)
        sys.exit(2)
