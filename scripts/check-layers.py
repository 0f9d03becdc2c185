#!/usr/bin/env python3
"""Checks the dependency rules of docs/architecture.md ("Layers") on the project's #includes.

  scripts/check-layers.py [ROOT]      exit 0 when every include keeps the rules, 1 otherwise
  scripts/check-layers.py --self-test checks that the rules catch what they should

Every layer folder may include its own headers and those of the layers it depends on, no others;
a few libraries may be included only where docs/architecture.md says. A violation is printed as
"<file>:<line>: <include> breaks <rule>".
"""
import os
import re
import sys
import tempfile

# The layers and what each may include, in dependency order (CMakeLists.txt builds them so).
ALLOWED = {
    "common": [],
    # A scene reads its environment map from an EXR file.
    "scene": ["common", "image"],
    "image": ["common"],
    "reference": ["common", "scene", "image"],
    "realtime": ["common", "scene", "image"],
    # The profiler's record is plain data; the timing summaries read it without linking GL.
    "metrics": ["common", "image", "realtime/gl/pass_record.h"],
    "results": ["common", "image", "metrics"],
    "suites": ["common", "scene", "image", "reference", "realtime", "metrics", "results"],
    "reports": ["common", "image", "metrics", "results"],
}
EVERYTHING = ["common", "scene", "image", "reference", "realtime", "metrics", "results",
              "suites", "reports", "cli", "tests", "bench", "fuzz"]
for top in ("cli", "tests", "bench", "fuzz"):
    ALLOWED[top] = EVERYTHING

# Headers of heavy or platform libraries, and the only places that may include them.
CONFINED = [
    (re.compile(r"<(OpenImageIO|OpenColorIO)/"), ("image/", "tests/image/"), ".cpp",
     "OpenImageIO and OpenColorIO only in image/*.cpp and its tests (their headers are heavy)"),
    (re.compile(r"<embree3/"), ("reference/",), ".cpp", "Embree only in reference/*.cpp"),
    (re.compile(r"<(GL|EGL)/"), ("realtime/", "tests/", "bench/"), "",
     "GL and EGL headers only in realtime/ (and its tests and benchmarks)"),
]

INCLUDE = re.compile(r'^\s*#\s*include\s+([<"])([^>"]+)[>"]')
SOURCES = (".cpp", ".h", ".glsl")


def layer_of(path):
    return path.split("/", 1)[0]


def allowed(path, target):
    """Whether `path` (relative to the root) may include the project header `target`."""
    layer = layer_of(path)
    target_layer = layer_of(target)
    if target_layer == "gib":  # generated headers (version, renderer version)
        return True
    if target_layer == layer:
        return realtime_internal_rule(path, target)
    for entry in ALLOWED.get(layer, []):
        if target == entry or target_layer == entry:
            return True
    return False


def realtime_internal_rule(path, target):
    """Inside realtime/: a technique includes no other technique, and the shared building blocks
    include no technique, except the catalogue (realtime/technique.cpp) that lists them all."""
    if not target.startswith("realtime/techniques/"):
        return True
    if path == "realtime/technique.cpp":
        return True
    if not path.startswith("realtime/techniques/"):
        return False
    return path.split("/")[2] == target.split("/")[2]


def project_header(target):
    return layer_of(target) in ALLOWED or layer_of(target) == "gib"


def check(root):
    problems = []
    for directory in EVERYTHING:
        base = os.path.join(root, directory)
        for folder, _, files in os.walk(base):
            for name in sorted(files):
                if not name.endswith(SOURCES):
                    continue
                full = os.path.join(folder, name)
                path = os.path.relpath(full, root).replace(os.sep, "/")
                with open(full, encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        kind, target = m.groups()
                        if kind == '"' and project_header(target):
                            if not allowed(path, target):
                                problems.append(f"{path}:{number}: #include \"{target}\" breaks the "
                                                f"rule of layer '{layer_of(path)}' (it may include "
                                                f"{describe(path)})")
                        for pattern, places, suffix, rule in CONFINED:
                            if pattern.match("<" + target) and not (
                                    path.startswith(places) and path.endswith(suffix)):
                                problems.append(f"{path}:{number}: #include <{target}> breaks: {rule}")
    return problems


def describe(path):
    layer = layer_of(path)
    if layer == "realtime":
        return "common, scene, image and realtime, but no other technique's folder"
    names = ALLOWED.get(layer, [])
    return ", ".join(names + [layer]) if names else layer + " only"


def self_test():
    files = {
        "common/a.h": '#include "common/b.h"\n',
        "scene/s.cpp": '#include "image/i.h"\n#include "reference/r.h"\n',       # 1 bad
        "metrics/m.h": '#include "realtime/gl/pass_record.h"\n#include "realtime/gl/gl.h"\n',  # 1
        "results/r.cpp": '#include "metrics/m.h"\n#include "suites/x.h"\n',      # 1 bad
        "reports/p.cpp": '#include "results/r.h"\n#include "gib/version.h"\n',
        "realtime/techniques/a/a.cpp": '#include "realtime/techniques/b/b.h"\n',  # 1 bad
        "realtime/lighting/l.cpp": '#include "realtime/techniques/a/a.h"\n',      # 1 bad
        "realtime/technique.cpp": '#include "realtime/techniques/a/a.h"\n',
        "image/x.h": "#include <OpenImageIO/imageio.h>\n",                         # 1 bad
        "reference/e.cpp": "#include <embree3/rtcore.h>\n",
        "cli/c.cpp": '#include "suites/x.h"\n#include <GL/gl.h>\n',               # 1 bad
    }
    with tempfile.TemporaryDirectory() as root:
        for path, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(root, path), "w") as f:
                f.write(text)
        problems = check(root)
    expected = ["scene/s.cpp:2", "metrics/m.h:2", "results/r.cpp:2", "realtime/techniques/a/a.cpp:1",
                "realtime/lighting/l.cpp:1", "image/x.h:1", "cli/c.cpp:2"]
    found = [p.split(": ", 1)[0] for p in problems]
    if sorted(found) != sorted(expected):
        print("self-test failed: expected violations at", sorted(expected), "found", problems)
        return 1
    print(f"self-test passed: {len(expected)} planted violations found, nothing else")
    return 0


def main(argv):
    if len(argv) > 1 and argv[1] == "--self-test":
        return self_test()
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    problems = check(root)
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} include(s) break the layer rules of docs/architecture.md")
        return 1
    print("every #include keeps the layer rules of docs/architecture.md")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
