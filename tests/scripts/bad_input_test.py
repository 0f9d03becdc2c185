#!/usr/bin/env python3
"""Runs every bad-input case of tests/cli/bad_input_cases.toml through gibench and checks what a
user relies on: the expected exit code, nothing on stdout, one line on stderr that starts with
"gibench: " and names the problem, and no file left behind. Then checks that docs/bad-input.md is
the table of exactly these cases with the messages gibench printed (so the document cannot go
stale), or rewrites it with --write-doc.

  tests/scripts/bad_input_test.py GIBENCH SOURCE_DIR [--write-doc]

Exit 0 when every case holds and the document is current, 1 otherwise.
"""
import os
import shlex
import subprocess
import sys
import tempfile
import tomllib

DOC = "docs/bad-input.md"


def files_in(directory):
    found = set()
    for root, dirs, names in os.walk(directory):
        for name in dirs + names:
            found.add(os.path.relpath(os.path.join(root, name), directory))
    return found


def run_case(gibench, case):
    with tempfile.TemporaryDirectory(prefix="gibench-bad-input-") as work:
        for name, text in case.get("files", {}).items():
            path = os.path.join(work, name)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        before = files_in(work)
        env = dict(os.environ, GIBENCH_STORE=os.path.join(work, "default-store"))
        result = subprocess.run([gibench] + shlex.split(case["command"]), cwd=work, env=env,
                                capture_output=True, text=True, timeout=120)
        left = sorted(files_in(work) - before)
        # A message may name a file by its absolute path: the document shows it relative.
        stderr = result.stderr.replace(os.path.realpath(work) + "/", "").replace(work + "/", "")
    problems = []
    expected_exit = case.get("exit", 2)
    if result.returncode != expected_exit:
        problems.append(f"exit code {result.returncode}, not {expected_exit}")
    if result.stdout:
        problems.append(f"printed on stdout: {result.stdout[:200]!r}")
    lines = stderr.splitlines()
    if len(lines) != 1 or not lines[0].startswith("gibench: "):
        problems.append(f"stderr is not one 'gibench: ' line: {stderr[:400]!r}")
    elif case["message"] not in lines[0]:
        problems.append(f"the message does not contain {case['message']!r}: {lines[0]!r}")
    if "internal error" in stderr:
        problems.append("an internal error")
    if left:
        problems.append(f"left behind: {', '.join(left)}")
    return (lines[0] if lines else ""), problems


def document(cases, messages):
    """The Markdown table of the cases, grouped by command, in the file's order."""
    groups = {}
    for case, message in zip(cases, messages):
        groups.setdefault(case["command"].split()[0], []).append((case, message))
    out = ["# Bad input, counted", "",
           "Every case of `tests/cli/bad_input_cases.toml`, run by the test `BadInput.*`",
           "(`tests/scripts/bad_input_test.py`), which also checks that this page lists exactly",
           "them with the message `gibench` printed. Each exits with the code given, prints one",
           "line on stderr and nothing else, and leaves no file behind. Regenerate with",
           "`tests/scripts/bad_input_test.py build/release/cli/gibench . --write-doc`.", "",
           f"{len(cases)} cases in {len(groups)} commands.", ""]
    for command, entries in groups.items():
        out += [f"## `gibench {command}` ({len(entries)})", "",
                "| command line | exit | message |", "|---|---|---|"]
        for case, message in entries:
            cell = message.replace("|", "\\|")
            out.append(f"| `gibench {case['command']}` | {case.get('exit', 2)} | {cell} |")
        out.append("")
    return "\n".join(out)


def main():
    if len(sys.argv) < 3:
        print("usage: bad_input_test.py GIBENCH SOURCE_DIR [--write-doc]", file=sys.stderr)
        return 2
    gibench, source = os.path.abspath(sys.argv[1]), sys.argv[2]
    with open(os.path.join(source, "tests/cli/bad_input_cases.toml"), "rb") as f:
        cases = tomllib.load(f)["case"]
    failed = 0
    messages = []
    for case in cases:
        message, problems = run_case(gibench, case)
        messages.append(message)
        if problems:
            failed += 1
            print(f"FAIL gibench {case['command']}: {'; '.join(problems)}")
    text = document(cases, messages)
    doc = os.path.join(source, DOC)
    if "--write-doc" in sys.argv:
        with open(doc, "w", encoding="utf-8") as f:
            f.write(text)
    else:
        current = open(doc, encoding="utf-8").read() if os.path.exists(doc) else ""
        if current != text:
            failed += 1
            print(f"FAIL {DOC} is not the table of these cases; regenerate it with "
                  f"tests/scripts/bad_input_test.py GIBENCH SOURCE_DIR --write-doc")
    print(f"bad input: {len(cases)} cases, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
