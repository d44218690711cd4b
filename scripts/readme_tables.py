"""Writes one benchmark table into docs/performance.md, between its own markers, and nothing else.

The generated tables live in docs/performance.md (PERFORMANCE_MD; the README links it and holds
only a hand-picked headline table). Its tables are one block,
<!-- perf-table:begin --> ... <!-- perf-table:end -->, holding one sub-block per table: <!-- perf-KEY:begin --> ... <!-- perf-KEY:end --> (KEY is
"predicates", "delaunay2d", "delaunay3d", "constrained3d"). write_block replaces what lies between one KEY's
markers, inserting them first (with a heading, at the end of the perf-table block) if absent.
Used by scripts/bench_predicates_table.py, bench_delaunay2d.py, bench_delaunay3d.py and
bench_constrained3d.py and bench_report.py, so that every table is written the same way; each
takes --update-readme (the option's historical name) to write it and --readme PATH for another file.
"""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PERFORMANCE_MD = os.path.join(ROOT, "docs", "performance.md")

BLOCK = ("<!-- perf-table:begin -->", "<!-- perf-table:end -->")


def markers(key):
    return f"<!-- perf-{key}:begin -->", f"<!-- perf-{key}:end -->"


def replace_block(readme, key, heading, producer, text):
    """The README text with KEY's block holding `producer` (one line saying which command made
    the table), a blank line and `text`. Raises ValueError if the markers are missing or out of
    place."""
    begin, end = BLOCK
    if begin not in readme or end not in readme:
        raise ValueError(f"markers {begin} / {end} not found")
    own_begin, own_end = markers(key)
    if own_begin not in readme:
        at = readme.index(end)
        readme = readme[:at] + f"\n### {heading}\n\n{own_begin}\n{own_end}\n" + readme[at:]
    if not readme.index(begin) < readme.index(own_begin) < readme.index(own_end) < readme.index(end):
        raise ValueError(f"{own_begin} / {own_end} must lie inside {begin} / {end}")
    head = readme[:readme.index(own_begin) + len(own_begin)]
    tail = readme[readme.index(own_end):]
    return head + "\n" + producer + "\n\n" + text.rstrip("\n") + "\n" + tail


def write_block(path, key, heading, producer, text):
    """replace_block on the file at `path`; exits with a message naming the file on error."""
    with open(path) as f:
        readme = f.read()
    try:
        readme = replace_block(readme, key, heading, producer, text)
    except ValueError as e:
        raise SystemExit(f"{path}: {e}")
    with open(path, "w") as f:
        f.write(readme)
    print(f"updated {path} ({key})", file=sys.stderr, flush=True)
