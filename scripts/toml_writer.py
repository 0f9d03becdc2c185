"""Writes TOML from Python values: what the scripts that generate suites share
(scripts/compare-suite-metrics.py writes shrunk copies of the shipped suites,
scripts/gpu_figures_suite.py the GPU figures' suite). tomllib reads TOML; the standard library
writes none.
"""
import json
import math
import re

BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def key(name):
    """A bare key where TOML allows one, else a quoted one."""
    return name if BARE_KEY.fullmatch(name) else json.dumps(name, ensure_ascii=False)


def value(v):
    """An inline value: booleans, numbers, strings (a JSON string is a TOML basic string), arrays
    and inline tables. Raises ValueError for what TOML cannot hold (a non-finite number here)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        if isinstance(v, float) and not math.isfinite(v):
            raise ValueError(f"non-finite number {v} cannot be written as TOML")
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list):
        return "[" + ", ".join(value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{key(k)} = {value(x)}" for k, x in v.items()) + " }"
    raise ValueError(f"cannot write {v!r} as TOML")


def is_table_array(v):
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def table_lines(path, table, lines, element=False):
    """Appends the members of `table` to `lines`: its plain values first; then its tables, those
    inside an array element inline (a case's `set`, `reference`), those inside a top-level table
    under their own header ([defaults.reference]); then its arrays of tables ([[case]])."""
    for k, v in table.items():
        if not is_table_array(v) and not (isinstance(v, dict) and not element):
            lines.append(f"{key(k)} = {value(v)}")
    for k, v in table.items():
        if isinstance(v, dict) and not element:
            lines += ["", f"[{path}{key(k)}]"]
            table_lines(f"{path}{key(k)}.", v, lines, element)
        elif is_table_array(v):
            for item in v:
                lines += ["", f"[[{path}{key(k)}]]"]
                table_lines(f"{path}{key(k)}.", item, lines, True)
    return lines
