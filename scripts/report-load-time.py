#!/usr/bin/env python3
"""Page weight and load time of a run's HTML report, measured in headless Chromium.

  scripts/report-load-time.py RUN_DIR [--repeat N] [--chromium PATH]

Weight: each page's bytes plus every file its src attributes name (pictures, viewer data), as a
browser reads them opening the page from disk. Load time: the page's own navigation-to-load
time, which the report's self-check records on <html data-load-ms> (median of N loads, each in a
fresh headless Chromium), for the index and the heaviest page under report/ (job and figure
pages); the self-check must pass.
Prints one table; exit 2 on bad input (no such run directory, no report, no Chromium).
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import urllib.parse

SOURCE = re.compile(r'src="([^"]+)"')


def fail(message):
    print(f"report-load-time: {message}", file=sys.stderr)
    sys.exit(2)


def weight(page):
    with open(page, encoding="utf-8") as f:
        html = f.read()
    total = os.path.getsize(page)
    for source in set(SOURCE.findall(html)):
        if source.startswith("data:"):
            continue
        path = os.path.join(os.path.dirname(page), urllib.parse.unquote(source))
        if os.path.isfile(path):
            total += os.path.getsize(path)
    return total


def root_attribute(dom, name):
    match = re.search(r"<html[^>]*\s" + re.escape(name) + r'="([^"]*)"', dom)
    return match.group(1) if match else ""


def load_ms(chromium, page, work):
    profile = tempfile.mkdtemp(dir=work)
    url = "file://" + urllib.parse.quote(os.path.abspath(page))
    run = subprocess.run(
        [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
         "--user-data-dir=" + profile, "--dump-dom", url],
        capture_output=True, text=True, timeout=120, env=dict(os.environ, HOME=profile))
    check = root_attribute(run.stdout, "data-report-check")
    if run.returncode != 0 or check != "ok":
        fail(f"{page} did not pass its self-check ({check or 'no result'}); keep the run "
             "directory whole")
    return float(root_attribute(run.stdout, "data-load-ms"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    args = parser.parse_args()
    index = os.path.join(args.run_dir, "index.html")
    if not os.path.isfile(index):
        fail(f"'{args.run_dir}' holds no index.html; give a run directory with its report "
             "(`gibench report DIR` writes one)")
    if not os.path.isfile(args.chromium):
        fail(f"no Chromium at '{args.chromium}'; install it (scripts/install-deps.sh) or give "
             "--chromium PATH")
    if args.repeat < 1:
        fail("--repeat must be 1 or more")
    report = os.path.join(args.run_dir, "report")
    pages = sorted(os.path.join(report, name) for name in os.listdir(report)
                   if name.endswith(".html")) if os.path.isdir(report) else []
    weights = {page: weight(page) for page in pages}
    heaviest = max(pages, key=weights.get) if pages else None
    with tempfile.TemporaryDirectory() as work:
        rows = [("index.html", weight(index),
                 statistics.median(load_ms(args.chromium, index, work) for _ in range(args.repeat)))]
        if heaviest:
            rows.append((os.path.relpath(heaviest, args.run_dir), weights[heaviest],
                         statistics.median(load_ms(args.chromium, heaviest, work)
                                           for _ in range(args.repeat))))
    print(f"{'page':60} {'weight (KiB)':>12} {'load (ms)':>10}")
    for name, size, ms in rows:
        print(f"{name:60} {size / 1024:12.1f} {ms:10.0f}")
    total = sum(weights.values())
    print(f"{len(pages)} pages under report/: {total / 1024 / 1024:.1f} MiB in all, "
          f"{(total / len(pages) if pages else 0) / 1024:.1f} KiB each on average "
          f"(median of {args.repeat} loads per page)")


if __name__ == "__main__":
    main()
