#!/usr/bin/env python3
"""Adds a real-time technique: the first step of docs/architecture.md, "Adding a technique".

  scripts/new-technique.py NAME --source "Author, Title, §x.y" [--description "one line"]
                           [--root DIR]

Writes a technique that builds and renders the shared surface lighting (G-buffer, emission,
direct light: realtime/lighting/surface_lighting.h), the starting point of every technique that
adds light to it, and puts it everywhere a technique must be:

  realtime/techniques/NAME/NAME_technique.{h,cpp}   the class and its TechniqueInfo
  realtime/techniques/NAME/README.md                 the technique's page, with the generated block
  tests/realtime/NAME_test.cpp                       its first tests
  realtime/technique.cpp                             the catalogue entry
  suites/nightly.toml                                nightly cases on the scenes of `direct`'s
  README.md                                          a row of the techniques table

Then build, run scripts/update-technique-docs.py (the README's parameters and passes) and the
technique's tests; the guide says what to replace first. Bad input (a name that is not
snake_case, a technique that exists) is one line on stderr and exit code 2, with nothing written.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tomllib

NAME = re.compile(r"^[a-z][a-z0-9]*(_[a-z0-9]+)*$")
CATALOGUE = "realtime/technique.cpp"
NIGHTLY = "suites/nightly.toml"
README = "README.md"


class BadInput(Exception):
    pass


class OneLineParser(argparse.ArgumentParser):
    """Bad usage is one line and exit code 2, as everywhere in GI Bench."""

    def error(self, message):
        print(f"new-technique.py: {message}; see --help", file=sys.stderr)
        sys.exit(2)


def camel(name, upper):
    parts = name.split("_")
    head = parts[0].capitalize() if upper else parts[0]
    return head + "".join(p.capitalize() for p in parts[1:])


def read(root, path):
    full = os.path.join(root, path)
    if not os.path.isfile(full):
        raise BadInput(f"{full} does not exist; give --root the repository's root")
    with open(full, encoding="utf-8") as f:
        return f.read()


def technique_header(name, cls, info_fn, description, source):
    return f"""// `{name}`: {description} ({source}). It draws the shared surface lighting (G-buffer,
// emission, direct light) and adds its own light after; see README.md beside this file.
#pragma once

#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"

namespace gib::rt {{

class {cls} final : public Technique {{
 public:
  explicit {cls}(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override {{ return {{0, 1}}; }}

 private:
  SurfaceLighting surface_lighting_;
  const GpuScene* scene_ = nullptr;
}};

TechniqueInfo {info_fn}();

}}  // namespace gib::rt
"""


def technique_source(name, cls, info_fn, description, source):
    def quoted(text):
        return text.replace("\\", "\\\\").replace('"', '\\"')

    return f"""#include "realtime/techniques/{name}/{name}_technique.h"

namespace gib::rt {{

{cls}::{cls}(const ParameterValues& p) : surface_lighting_(p) {{}}

void {cls}::prepare(const GpuScene& scene, int width, int height) {{
  scene_ = &scene;
  surface_lighting_.prepare(scene, width, height);
}}

void {cls}::render(Frame& frame) {{
  surface_lighting_.render(*scene_, frame.target, frame.profiler);
}}

TechniqueInfo {info_fn}() {{
  TechniqueInfo info;
  info.name = "{name}";
  info.description = "{quoted(description)}";
  info.source = "{quoted(source)}";
  info.parameters = joinParameterTables({{SurfaceLighting::parameters()}});
  SurfaceLighting::declarePasses(info.passes);
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {{
    return std::make_unique<{cls}>(values);
  }};
  return info;
}}

}}  // namespace gib::rt
"""


def technique_test(name, cls):
    return f"""// `{name}` as the scaffold wrote it: the shared surface lighting alone, so its image is
// `direct`'s. Replace the first test by the technique's own checks against the reference of its
// path class (docs/architecture.md, "Adding a technique").
#include "realtime/techniques/{name}/{name}_technique.h"

#include "common/input_error.h"
#include "realtime/technique_runner.h"
#include "scene/builtin_scenes.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <span>

namespace gib::rt {{
namespace {{

TEST({cls}, RendersTheSurfaceLightingOfDirect) {{
  const scene::Scene cornell = scene::loadScene("cornell");
  const TechniqueRunResult ours = test::renderOneFrame(cornell, "{name}", {{"light_samples=4"}}, 32);
  const TechniqueRunResult direct = test::renderOneFrame(cornell, "direct", {{"light_samples=4"}}, 32);
  EXPECT_EQ(image::countNonFinite(ours.image), 0u);
  const std::span<const float> a = ours.image.data(), b = direct.image.data();
  EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
}}

TEST({cls}, RefusesAParameterOutOfRangeNamingIt) {{
  const TechniqueInfo& info = findTechnique("{name}");
  try {{
    parseParameters(info.parameters, {{"light_samples=0"}}, "technique '{name}'");
    ADD_FAILURE() << "light_samples=0 was accepted";
  }} catch (const InputError& e) {{
    EXPECT_NE(std::string(e.what()).find("technique '{name}' parameter 'light_samples'"),
              std::string::npos)
        << e.what();
  }}
}}

}}  // namespace
}}  // namespace gib::rt
"""


def technique_readme(name, description, source):
    return f"""# `{name}`

{description}. Source: {source}.

## What the document does

(The section's method, its parameters and the figures it reports, in your words.)

## What this implementation does

The scaffold (`scripts/new-technique.py`) draws the shared surface lighting
(`realtime/lighting/surface_lighting.h`): the G-buffer, what the camera sees of emitters and the
sky, and the direct light of every light sample with shadow maps, as `direct` does.

<!-- BEGIN generated by `gibench list techniques --markdown {name}` (scripts/update-technique-docs.py) -->
<!-- END generated -->

## Measured

(Error against the reference of its path class, and frame times, with date and machine; the
figure suite that reproduces the document's figures.)

## Corrections to the document

(Misprints found and how they were corrected, each cited.)
"""


def add_to_catalogue(text, name, info_fn):
    include = f'#include "realtime/techniques/{name}/{name}_technique.h"\n'
    includes = re.findall(r'#include "realtime/techniques/[^"]+"\n', text)
    if not includes:
        raise BadInput(f"{CATALOGUE} has no technique includes; is --root the repository's root?")
    # Keep the includes sorted: insert before the first that sorts after the new one.
    after = [i for i in includes if i > include]
    if after:
        text = text.replace(after[0], include + after[0], 1)
    else:
        text = text.replace(includes[-1], includes[-1] + include, 1)
    entries = re.search(r"(catalogue = \{)(.*?)(\};)", text, re.S)
    if not entries:
        raise BadInput(f"{CATALOGUE} has no `catalogue = {{…}};` list")
    body = entries.group(2).rstrip()
    body += f",\n      {info_fn}()"
    return text[:entries.start(2)] + body + text[entries.end(2):]


def add_to_nightly(text, name):
    """A case on every scene where the nightly suite runs `direct`, with its reference settings:
    the scaffold renders what `direct` renders, on every scene (the nightly test fails when a
    scene the technique can render has no case)."""
    try:
        suite = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise BadInput(f"{NIGHTLY} is not valid TOML ({e}); fix it first")
    cases = [c for c in suite.get("case", []) if c.get("technique") == "direct"]
    if not cases:
        raise BadInput(f"{NIGHTLY} has no case of `direct` to follow")
    out = text.rstrip("\n") + f"""

# {name}: every scene of `direct`'s cases (scripts/new-technique.py); add the sweeps its document
# measures."""
    for case in cases:
        out += f'\n\n[[case]]\nscene = "{case["scene"]}"\ntechnique = "{name}"'
        spp = case.get("reference", {}).get("spp")
        if spp is not None:
            out += f"\nreference = {{ spp = {spp} }}"
    return out + "\n"


def add_to_readme(text, name, source):
    rows = list(re.finditer(r"^\| `[a-z0-9_]+` \|.*\|\n", text, re.M))
    if not rows:
        raise BadInput(f"{README} has no techniques table (rows `| \\`name\\` | … |`)")
    row = (f"| `{name}` | {source} | "
           f"[realtime/techniques/{name}](realtime/techniques/{name}/README.md) |\n")
    end = rows[-1].end()
    return text[:end] + row + text[end:]


def plan(root, name, source, description):
    if not NAME.match(name):
        raise BadInput(f"technique name '{name}' is not snake_case; give e.g. distance_maps")
    if not source.strip():
        raise BadInput("--source is empty; give the document and section, e.g. \"book §6.1\"")
    folder = os.path.join("realtime", "techniques", name)
    if os.path.exists(os.path.join(root, folder)):
        raise BadInput(f"{os.path.join(root, folder)} exists; choose another name")
    catalogue = read(root, CATALOGUE)
    if f'info.name = "{name}"' in catalogue or f"{camel(name, False)}TechniqueInfo()" in catalogue:
        raise BadInput(f"technique '{name}' is already in {CATALOGUE}; choose another name")
    cls = camel(name, True) + "Technique"
    info_fn = camel(name, False) + "TechniqueInfo"
    description = description or f"{name.replace('_', ' ')} over the shared surface lighting"
    test = os.path.join("tests", "realtime", f"{name}_test.cpp")
    if os.path.exists(os.path.join(root, test)):
        raise BadInput(f"{os.path.join(root, test)} exists; choose another name")
    return {
        os.path.join(folder, f"{name}_technique.h"):
            technique_header(name, cls, info_fn, description, source),
        os.path.join(folder, f"{name}_technique.cpp"):
            technique_source(name, cls, info_fn, description, source),
        os.path.join(folder, "README.md"): technique_readme(name, description, source),
        test: technique_test(name, cls),
        CATALOGUE: add_to_catalogue(catalogue, name, info_fn),
        NIGHTLY: add_to_nightly(read(root, NIGHTLY), name),
        README: add_to_readme(read(root, README), name, source),
    }


def main(argv):
    parser = OneLineParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("name")
    parser.add_argument("--source", required=True)
    parser.add_argument("--description", default="")
    parser.add_argument("--root", default=os.path.normpath(os.path.join(os.path.dirname(__file__),
                                                                        "..")))
    args = parser.parse_args(argv[1:])
    try:
        files = plan(args.root, args.name, args.source, args.description)
    except BadInput as e:
        print(f"new-technique.py: {e}", file=sys.stderr)
        return 2
    # Everything is computed before anything is written: bad input leaves no file behind.
    for path, text in files.items():
        full = os.path.join(args.root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w", encoding="utf-8") as f:
            f.write(text)
        print(f"wrote {path}")
    # The house style (clang-format) on the C++ written, where the tool is installed.
    cpp = [os.path.join(args.root, p) for p in files if p.endswith((".h", ".cpp"))]
    if shutil.which("clang-format"):
        subprocess.run(["clang-format", "-i", *cpp], check=True)
    print(f"next: build; scripts/update-technique-docs.py; "
          f"ctest -R '{camel(args.name, True)}Technique|TechniqueCatalogue|TechniqueDocs|Nightly'; "
          f"then docs/architecture.md, \"Adding a technique\"")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
