#!/usr/bin/env python3
"""Checks that the documentation's cross-references point at files and headings that exist.

  tests/scripts/docs_references_test.py ROOT      exit 0 when every reference resolves, 1 otherwise
  tests/scripts/docs_references_test.py --self-test   checks that planted broken references are found

Docs and comments cite a section by file and heading, `docs/harness.md, "Timing verdicts"` (also
written `docs/X.md ("Heading")` or `docs/X.md "Heading"`, and wrapped over comment lines), and
Markdown pages link with `[text](path#anchor)` and `[text](path)`. When a heading is renamed or
a section moves, nothing else notices: the citation silently points nowhere. This test reads
README.md, the pages under docs/, every technique's README, the suites' comments and the sources
of every layer, scripts, tests and benchmarks, and prints one line per broken reference,
"<file>:<line>: <reference>: <problem>; <the headings or files nearest to it>".

A cited heading matches a heading of the file exactly, or its beginning up to a ':' or ' (' (so
"Runs on many machines" cites "Runs on many machines: shards, `gibench merge` and Slurm"); an
anchor matches a heading's GitHub slug.
"""
import difflib
import os
import re
import sys
import tempfile

# Folders whose text files may cite the docs; fuzz corpora and test data are inputs, not prose.
SOURCE_DIRS = ["docs", "common", "scene", "image", "reference", "realtime", "metrics", "results",
               "suites", "reports", "cli", "tests", "bench", "fuzz", "scripts", "cmake", ".ci"]
SKIPPED_DIRS = {"fuzz/corpus", "fuzz/dictionaries", "tests/data"}
# This file's own planted references are broken on purpose.
SKIPPED_FILES = {"tests/scripts/docs_references_test.py"}
SOURCE_SUFFIXES = (".h", ".cpp", ".glsl", ".py", ".sh", ".toml", ".cmake", ".txt", ".md")
SOURCE_NAMES = {"run"}  # .ci/run

# A cited file: a path ending in .md, not the tail of a longer path or word.
PATH = r"(?<![\w./-])(?P<path>(?:[\w.-]+/)*[\w.-]+\.md)"
# Between file and heading: blanks, a comma or an opening parenthesis, and comment leaders where
# the citation wraps onto the next comment line. At least one character: `"a.md"` is a string.
SEPARATOR = r"(?P<sep>(?:[ \t,(]|\n[ \t]*(?://+|#+|\*(?!\*))?)+)"
HEADING_REFERENCE = re.compile(PATH + SEPARATOR + r'"(?P<heading>[^"]{1,160})"')
# A file named without a heading: only docs/ pages, so that test fixtures ("out.md") stay out.
DOC_MENTION = re.compile(r"(?<![\w./-])(?P<path>docs/[\w.-]+\.md)(?![\w/-])")
MARKDOWN_LINK = re.compile(r"!?\[[^\]\n]*\]\((?P<target>[^)\s]+)(?:\s+\"[^\"]*\")?\)")
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING_LINE = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
COMMENT_LEADER = re.compile(r"\n[ \t]*(?://+|#+|\*)?[ \t]*")


def headings_of(path):
    """The heading texts of a Markdown file, in order, leaving out fenced code."""
    headings = []
    in_fence = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if FENCE.match(line):
                in_fence = not in_fence
                continue
            match = None if in_fence else HEADING_LINE.match(line)
            if match:
                headings.append(match.group(2))
    return headings


def github_slug(heading):
    """The anchor GitHub gives a heading: lower case, punctuation dropped, blanks as hyphens."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link's text only
    text = re.sub(r"[^\w\- ]", "", text.lower())
    return text.replace(" ", "-")


def slugs_of(headings):
    slugs = []
    seen = {}
    for heading in headings:
        slug = github_slug(heading)
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        slugs.append(slug if count == 0 else f"{slug}-{count}")
    return slugs


def heading_matches(cited, heading):
    for candidate in (heading, heading.replace("`", "")):
        if candidate == cited or candidate.startswith((cited + ":", cited + " (")):
            return True
    return False


def nearest(word, choices):
    containing = [c for c in choices if word.lower() in c.lower()]
    close = difflib.get_close_matches(word, choices, n=3, cutoff=0.3)
    shown = containing[:3] or close or choices[:5]
    return ", ".join(f'"{c}"' for c in shown) if shown else "none"


class Checker:
    def __init__(self, root):
        self.root = os.path.abspath(root)
        self.headings = {}
        self.problems = []
        self.reported = set()
        self.checked = 0

    def rel(self, path):
        return os.path.relpath(path, self.root)

    def resolve(self, cited, citing_file):
        """The cited file: relative to the citing file's folder, else to the root."""
        for base in (os.path.dirname(citing_file), self.root):
            candidate = os.path.normpath(os.path.join(base, cited))
            if os.path.isfile(candidate):
                return candidate
        return None

    def headings_in(self, path):
        if path not in self.headings:
            self.headings[path] = headings_of(path)
        return self.headings[path]

    def report(self, citing_file, text, offset, reference, problem):
        line = text.count("\n", 0, offset) + 1
        # A link to a missing docs/ page is also a mention of it: one line for both.
        key = (citing_file, line, problem)
        if key not in self.reported:
            self.reported.add(key)
            self.problems.append(f"{self.rel(citing_file)}:{line}: {reference}: {problem}")

    def missing_file(self, cited, citing_file):
        folder = os.path.normpath(os.path.join(self.root, os.path.dirname(cited)))
        pages = sorted(n for n in os.listdir(folder) if n.endswith(".md")) \
            if os.path.isdir(folder) else []
        return f"no such file; nearest: {nearest(os.path.basename(cited), pages)}"

    def check_heading_references(self, path, text):
        for match in HEADING_REFERENCE.finditer(text):
            cited = COMMENT_LEADER.sub(" ", match.group("heading")).strip()
            cited = re.sub(r"\s+", " ", cited)
            shown = f'{match.group("path")}, "{cited}"'
            self.checked += 1
            target = self.resolve(match.group("path"), path)
            if target is None:
                self.report(path, text, match.start(),
                            shown, self.missing_file(match.group("path"), path))
                continue
            headings = self.headings_in(target)
            if not any(heading_matches(cited, h) for h in headings):
                self.report(path, text, match.start(), shown,
                            f"no such heading in {self.rel(target)}; nearest: "
                            f"{nearest(cited, headings)}")

    def check_doc_mentions(self, path, text):
        for match in DOC_MENTION.finditer(text):
            self.checked += 1
            if self.resolve(match.group("path"), path) is None:
                self.report(path, text, match.start(), match.group("path"),
                            self.missing_file(match.group("path"), path))

    def check_markdown_links(self, path, text):
        offset = 0
        in_fence = False
        for line in text.splitlines(keepends=True):
            if FENCE.match(line):
                in_fence = not in_fence
            elif not in_fence:
                for match in MARKDOWN_LINK.finditer(line):
                    self.check_link(path, text, offset + match.start(), match.group("target"))
            offset += len(line)

    def check_link(self, path, text, offset, target):
        if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # https:, mailto:
            return
        self.checked += 1
        file_part, _, anchor = target.partition("#")
        linked = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) \
            if file_part else path
        if not os.path.exists(linked):
            self.report(path, text, offset, f"({target})",
                        self.missing_file(os.path.relpath(linked, self.root), path))
            return
        if not anchor:
            return
        if not linked.endswith(".md") or not os.path.isfile(linked):
            self.report(path, text, offset, f"({target})", "an anchor into a file that is not a page")
            return
        headings = self.headings_in(linked)
        if anchor not in slugs_of(headings):
            self.report(path, text, offset, f"({target})",
                        f"no heading with anchor #{anchor} in {self.rel(linked)}; nearest: "
                        f"{nearest(anchor, slugs_of(headings))}")

    def check_file(self, path):
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        self.check_heading_references(path, text)
        self.check_doc_mentions(path, text)
        if path.endswith(".md"):
            self.check_markdown_links(path, text)


def files_to_check(root):
    files = [os.path.join(root, "README.md"), os.path.join(root, "CMakeLists.txt")]
    for top in SOURCE_DIRS:
        for folder, dirs, names in os.walk(os.path.join(root, top)):
            dirs[:] = sorted(d for d in dirs
                             if os.path.relpath(os.path.join(folder, d), root) not in SKIPPED_DIRS)
            for name in sorted(names):
                path = os.path.join(folder, name)
                if (name.endswith(SOURCE_SUFFIXES) or name in SOURCE_NAMES) and \
                        os.path.relpath(path, root) not in SKIPPED_FILES:
                    files.append(path)
    return [f for f in files if os.path.isfile(f)]


def check(root):
    checker = Checker(root)
    for path in files_to_check(checker.root):
        checker.check_file(path)
    return checker


def self_test():
    # Each planted broken reference names its line; the good ones beside them must pass.
    files = {
        "docs/guide.md": "# Guide\n\n## Runs on many machines: shards\n\n```toml\n# not a heading\n"
                         "```\n\n### Timing verdicts\n\nSee [the verdicts](#timing-verdicts) and "
                         "[nothing](#not-here).\n",                                     # 11 bad
        "README.md": 'Intro (docs/guide.md, "Timing verdicts").\n'
                     'Also docs/guide.md ("Runs on many machines").\n'
                     '[Guide](docs/guide.md#runs-on-many-machines-shards)\n'
                     'Broken: docs/guide.md, "Timing verdict".\n'                       # 4 bad
                     '[Gone](docs/gone.md) and [bad anchor](docs/guide.md#timing)\n'    # 5 bad x2
                     'Code: docs/guide.md, "not a heading".\n',                         # 6 bad
        "cli/a.cpp": '// Wrapped (docs/guide.md,\n// "Timing verdicts") is fine;\n'
                     '// this one (docs/guide.md, "Runs on\n// many places") is not.\n'   # 3 bad
                     'const char* k = "docs/guide.md";  // a string, not a citation\n'
                     '// docs/missing.md is gone.\n',                                   # 6 bad
        "suites/s.toml": '# (docs/guide.md "Timing verdicts")\n# docs/guide.md, "Guides"\n',  # 2
    }
    expected = ["docs/guide.md:11", "README.md:4", "README.md:5", "README.md:5", "README.md:6",
                "cli/a.cpp:3", "cli/a.cpp:6", "suites/s.toml:2"]
    with tempfile.TemporaryDirectory() as root:
        for path, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                f.write(text)
        checker = check(root)
    found = [p.split(": ", 1)[0] for p in checker.problems]
    if sorted(found) != sorted(expected):
        print("self-test failed: expected broken references at", sorted(expected), "found:")
        for problem in checker.problems:
            print("  " + problem)
        return 1
    if not any('nearest: "Timing verdicts"' in p for p in checker.problems):
        print("self-test failed: a misspelt heading does not name the heading nearest to it:")
        for problem in checker.problems:
            print("  " + problem)
        return 1
    print(f"self-test passed: {len(expected)} planted broken references found, nothing else")
    return 0


def main(argv):
    if len(argv) == 2 and argv[1] == "--self-test":
        return self_test()
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        print("usage: docs_references_test.py ROOT | --self-test (ROOT: the repository's root)",
              file=sys.stderr)
        return 2
    checker = check(argv[1])
    for problem in checker.problems:
        print(problem)
    if checker.problems:
        print(f"{len(checker.problems)} of {checker.checked} references point at no file or "
              f"heading; fix the reference, or the heading it meant")
        return 1
    print(f"all {checker.checked} references point at real files and headings")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
