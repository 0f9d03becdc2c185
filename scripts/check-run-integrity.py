#!/usr/bin/env python3
"""Checks what a run left on disk after a fault (docs/reliability.md, "Faults"): nothing that a
later run, `gibench report` or `gibench store verify` would trust may be partial.

  scripts/check-run-integrity.py GIBENCH --out DIR [--store DIR] [--db FILE] [--no-temporaries]

Checks: every JSON file parses; every HTML page ends with </html> and every page or image it
links inside the run directory exists; every EXR reads to its last pixel (oiiotool); `gibench store
verify` passes on the store (each entry's image matches its content hash and a fresh render);
the history database passes SQLite's integrity check and `gibench history` reads every run.
With --no-temporaries, also that no temporary file of an atomic write is left (a clean error
removes them; a killed process may leave them, and they are ignored and collected later).
Prints one line per problem and exits 1 when there is any, 0 otherwise.
"""
import argparse
import json
import os
import re
import sqlite3
import subprocess
import sys

TEMPORARY = re.compile(r"^\..*\.tmp-\d+-\d+$")  # image/atomic_write.cpp's temporary names
LOCAL_LINK = re.compile(r'(?:href|src)="(?!https?:|data:|#|mailto:)([^"#?]+)')


def files_under(root):
    for directory, _, names in os.walk(root):
        for name in names:
            yield os.path.join(directory, name)


def html_problems(path):
    """A page is whole, and links only to files that exist: the report writes the pages a page
    links before the page itself (reports/html_report.cpp). The exception is the link back to the
    run's index.html, which is written last, so that it never links a page not yet there."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    if not text.rstrip().endswith("</html>"):
        return [f"{path}: not a whole HTML page"]
    directory = os.path.dirname(path)
    return [f"{path}: links '{link}', which is not there"
            for link in sorted(set(LOCAL_LINK.findall(text)))
            if os.path.basename(link) != "index.html"
            and not os.path.exists(os.path.join(directory, link))]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("gibench")
    parser.add_argument("--out", required=True)
    parser.add_argument("--store")
    parser.add_argument("--db")
    parser.add_argument("--no-temporaries", action="store_true")
    args = parser.parse_args()
    problems = []
    for root in (args.out, args.store):
        if not root or not os.path.isdir(root):
            continue
        for path in files_under(root):
            name = os.path.basename(path)
            in_staging = "/.tmp-" in path  # a store entry being written: never read as an entry
            if TEMPORARY.match(name) or in_staging:
                if args.no_temporaries:
                    problems.append(f"{path}: a temporary file was left behind")
                continue
            if name.endswith(".json"):
                try:
                    with open(path, encoding="utf-8") as f:
                        json.load(f)
                except (ValueError, UnicodeDecodeError) as e:
                    problems.append(f"{path}: not whole JSON ({e})")
            elif name.endswith(".html"):
                problems.extend(html_problems(path))
            elif name.endswith(".exr"):
                read = subprocess.run(["oiiotool", path, "--printstats"], capture_output=True)
                if read.returncode != 0:
                    problems.append(f"{path}: not a whole EXR")
    if args.store and os.path.isdir(os.path.join(args.store, "references")):
        # At its default spp (64); entries stored below 32 spp fail as untestable
        # (suites/store_verification.h), so the fault scripts' suites store at 32 or more.
        verify = subprocess.run([args.gibench, "store", "verify", "--store", args.store],
                                capture_output=True, text=True)
        if verify.returncode != 0:
            problems.append(f"store verify failed: {verify.stdout.strip()} {verify.stderr.strip()}")
    if args.db and os.path.exists(args.db):
        with sqlite3.connect(args.db) as db:
            check = db.execute("PRAGMA integrity_check").fetchone()[0]
        if check != "ok":
            problems.append(f"{args.db}: integrity check says {check}")
        history = subprocess.run([args.gibench, "history", "--db", args.db, "--json"],
                                 capture_output=True, text=True)
        if history.returncode != 0:
            problems.append(f"{args.db}: gibench history failed: {history.stderr.strip()}")
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
