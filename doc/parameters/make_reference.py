#!/usr/bin/env python3
"""Turns bfemp's own JSON dump of its declared parameters into parameters.md.

Run through the build target `parameter_reference` (which first runs
`bfemp --print-parameters doc/parameters`), or by hand:
    build/bfemp --print-parameters doc/parameters
    python3 doc/parameters/make_reference.py doc/parameters
"""
import json
import re
import sys
from pathlib import Path


def entries(tree, path):
    """Yields (subsection path, entry name, entry dict) depth first."""
    for name, node in tree.items():
        if isinstance(node, dict) and "value" in node and "documentation" in node:
            yield path, name, node
    for name, node in tree.items():
        if isinstance(node, dict) and not ("value" in node and "documentation" in node):
            yield from entries(node, path + [name])


def unescape(name):
    # deal.II's JSON mangles spaces and some characters in names
    return re.sub(r"_([0-9a-f]{2})", lambda m: chr(int(m.group(1), 16)), name)


def simplify(pattern):
    """deal.II's pattern description in a few words."""
    p = pattern.strip("[] ")
    p = re.sub(r"Double -MAX_DOUBLE\.\.\.MAX_DOUBLE \(inclusive\)", "real", p)
    p = re.sub(r"Double (\S+)\.\.\.MAX_DOUBLE \(inclusive\)", r"real >= \1", p)
    p = re.sub(r"Integer range (\S+)\.\.\.2147483647 \(inclusive\)", r"integer >= \1", p)
    p = re.sub(r"Integer range (\S+)\.\.\.(\S+) \(inclusive\)", r"integer \1..\2", p)
    p = re.sub(r"List of <\[real\]> of length (\d)\.\.\.\d \(inclusive\)( separated by <,>)?",
               r"\1 comma-separated reals", p)
    p = re.sub(r"Selection (.*)", lambda m: " / ".join(x.strip() for x in m.group(1).split("|") if x.strip()), p)
    return p.replace("|", "/")


def table(json_file, title):
    tree = json.loads(Path(json_file).read_text())
    lines = [f"## {title}", ""]
    current = None
    for path, name, node in entries(tree, []):
        section = " / ".join(unescape(p) for p in path) or "(top level)"
        if section != current:
            lines += ["", f"### {section}", "",
                      "| entry | default | unit | allowed | meaning |",
                      "|---|---|---|---|---|"]
            current = section
        doc = node["documentation"]
        unit, text = "", doc
        match = re.match(r"\s*\[([^\]]*)\]\s*(.*)", doc, re.S)
        if match:
            unit, text = match.group(1), match.group(2)
        pattern = simplify(node.get("pattern_description", ""))
        cells = [unescape(name), f"`{node['default_value']}`", unit, pattern,
                 " ".join(text.split())]
        lines.append("| " + " | ".join(c.replace("\n", " ") for c in cells) + " |")
    return "\n".join(lines)


def main():
    folder = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    header = [
        "# bfemp parameter reference",
        "",
        "Generated from the code by `cmake --build build --target parameter_reference`",
        "(`bfemp --print-parameters doc/parameters` + this script); do not edit by hand.",
        "Every entry has a default; `parameters_2d.prm` / `parameters_3d.prm` beside this",
        "file are complete prm files with all defaults. Numbered subsections (`body 0`,",
        "`body 1`, ..., `primitive 0`, ..., `level set 0`, ...) repeat as many times as",
        "the corresponding `number of ...` entry says; one of each is listed.",
        "",
    ]
    body = [table(folder / "parameters_2d.json", "Entries (2D defaults; 3D points have three components)")]
    (folder / "parameters.md").write_text("\n".join(header + body) + "\n")
    print(f"wrote {folder / 'parameters.md'}")


if __name__ == "__main__":
    main()
