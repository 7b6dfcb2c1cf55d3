#!/usr/bin/env python3
#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#
# The library's include graph by layer (docs/architecture.md, "The layers";
# issue 28).
#
#   tools/include_layers.py                  print the graph by layer
#   tools/include_layers.py --check DOC      check DOC's layer table against it
#
# The layers are computed from the #include <spinslide/...> lines of every
# header under include/spinslide/, so that the rule "a header includes only
# headers of a lower layer, or detail/ helpers of its own" holds by
# construction:
#   P(h)      the public headers that h reaches through detail/ headers only
#             (h itself not counted);
#   layer(h)  1 + the largest layer in P(h), or, where P(h) is empty, 1 for a
#             public header and 0 for a detail/ one.
# A detail/ helper thus sits on the layer of the public headers it builds on,
# one above them, and never above a header that includes it.  A cycle is an
# error.
#
# --check reads the table of DOC (rows "| layer | `header`, `header` | owns |",
# a blank layer meaning the row above's) and fails, naming each difference,
# where a header is missing from the table, listed twice, listed but not in
# include/, or listed on another layer than the computed one.  It also checks
# the graph printed between the lines "<!-- include graph: begin -->" and
# "<!-- include graph: end -->" of DOC, which must be this script's output.
# Python 3 standard library only.

import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INCLUDE = os.path.join(ROOT, "include")
INCLUDE_RE = re.compile(r'^\s*#\s*include\s*<spinslide/([^>]+)>', re.M)


def headers():
    """Every header under include/spinslide/, as a path relative to it."""
    out = []
    base = os.path.join(INCLUDE, "spinslide")
    for d, _, files in os.walk(base):
        for f in files:
            if f.endswith(".hpp"):
                out.append(os.path.relpath(os.path.join(d, f), base).replace(os.sep, "/"))
    return sorted(out)


def includes(hs):
    """header -> the spinslide headers it includes."""
    graph = {}
    for h in hs:
        with open(os.path.join(INCLUDE, "spinslide", h), encoding="utf-8") as f:
            graph[h] = sorted(set(INCLUDE_RE.findall(f.read())) - {h})
    for h, deps in graph.items():
        for d in deps:
            if d not in graph:
                sys.exit(f"include_layers: {h} includes <spinslide/{d}>, which does not exist")
    return graph


def is_detail(h):
    return h.startswith("detail/")


def layers(graph):
    memo, active = {}, []

    def reached_public(h):
        seen, stack, out = set(), list(graph[h]), set()
        while stack:
            d = stack.pop()
            if d in seen:
                continue
            seen.add(d)
            if is_detail(d):
                stack.extend(graph[d])
            else:
                out.add(d)
        return out

    def layer(h):
        if h in memo:
            return memo[h]
        if h in active:
            sys.exit("include_layers: include cycle: " + " -> ".join(active[active.index(h):] + [h]))
        active.append(h)
        for d in graph[h]:  # a cycle through detail/ headers is found here too
            layer(d)
        above = [layer(p) for p in reached_public(h)]
        active.pop()
        memo[h] = 1 + max(above) if above else (0 if is_detail(h) else 1)
        return memo[h]

    return {h: layer(h) for h in graph}


def graph_text(graph, lay):
    """The graph by layer, one line per header: its includes."""
    lines = []
    for n in range(max(lay.values()) + 1):
        lines.append(f"layer {n}")
        for h in sorted(x for x in graph if lay[x] == n):
            deps = ", ".join(f"{d} ({lay[d]})" for d in graph[h]) or "-"
            lines.append(f"  {h} <- {deps}")
    return lines


def table_layers(doc_text):
    """header -> [layers] from the doc's layer table."""
    rows, current = {}, None
    for line in doc_text.splitlines():
        m = re.match(r'^\|\s*([^|]*?)\s*\|\s*([^|]*?)\s*\|', line)
        if not m or line.startswith("| layer") or set(line) <= set("|- "):
            continue
        cell, names = m.group(1), m.group(2)
        num = re.match(r'^(\d+)', cell)
        if num:
            current = int(num.group(1))
        if current is None:
            continue
        for name in re.findall(r'`([^`]+\.hpp)`', names):
            rows.setdefault(name, []).append(current)
    return rows


def check(doc, graph, lay):
    with open(doc, encoding="utf-8") as f:
        text = f.read()
    problems = []
    table = table_layers(text)
    for h in sorted(graph):
        listed = table.get(h, [])
        if not listed:
            problems.append(f"{h}: not in the table (computed layer {lay[h]})")
        elif len(listed) > 1:
            problems.append(f"{h}: listed {len(listed)} times")
        elif listed[0] != lay[h]:
            problems.append(f"{h}: on layer {listed[0]} in the table, computed {lay[h]}")
    for h in sorted(set(table) - set(graph)):
        problems.append(f"{h}: in the table but not in include/spinslide/")
    m = re.search(r'<!-- include graph: begin -->\n```\n(.*?)```\n<!-- include graph: end -->',
                  text, re.S)
    if not m:
        problems.append("no graph between <!-- include graph: begin --> and <!-- include graph: end -->")
    elif m.group(1).splitlines() != graph_text(graph, lay):
        problems.append("the printed graph is not this script's output (regenerate it)")
    for p in problems:
        print(f"{doc}: {p}")
    print(f"include_layers: {len(graph)} headers, {max(lay.values()) + 1} layers, "
          f"{len(problems)} difference(s) from {doc}")
    return 1 if problems else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--check", metavar="DOC", help="check DOC's layer table and graph")
    args = ap.parse_args()
    graph = includes(headers())
    lay = layers(graph)
    if args.check:
        return check(args.check, graph, lay)
    print("\n".join(graph_text(graph, lay)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
