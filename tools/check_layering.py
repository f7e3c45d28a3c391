#!/usr/bin/env python3
"""Checks that every stage of casteljau includes only what it may use.

casteljau's library is a pipeline of stages, each a folder under src/ with its public headers in
include/casteljau/. A stage may use the stages listed under it in STAGES below (and, through them,
theirs), never one above it nor one beside it. This script reads every `#include "..."` of every
file under src/ and include/casteljau/ and reports, one line per offending include:

  - an include of a stage the including stage may not use (an arrow up, or across);
  - an include of another stage's private header (a header under src/<stage>/) that is not one of
    the INTERNAL_INTERFACES, or any such header from a stage that may use public headers only;
  - a public (installed) header that includes a private (not installed) one;
  - a header that cannot be found, a file or public header that belongs to no stage;
  - a cycle of includes between files.

STAGES is the single source of truth for the layering: docs/ARCHITECTURE.md describes it, and each
stage's CMake target (CMakeLists.txt) shows only the folders of the stages it may use.

Usage: tools/check_layering.py [--root DIR]   (DIR: the repository, default: this script's ../)
       tools/check_layering.py --cmake        (prints STAGES as CMake variables for the build)
Exit status: 0 when every include is allowed, 1 otherwise.
"""

import argparse
import re
import sys
from pathlib import Path

# The stages, lowest first: (name, stages it uses directly, its public headers in include/casteljau/).
# A stage's folder is src/<name>/. A stage may use the stages it names and, transitively, the ones
# they use; each named stage must come earlier in the list, so the arrows can only point down.
STAGES = [
    ("core", [], ["error.hpp", "limits.hpp", "threads.hpp", "file_io.hpp"]),
    ("geometry", ["core"], ["geometry.hpp", "vec.hpp"]),
    ("path", ["geometry"], ["path.hpp", "arc.hpp", "svg_path.hpp", "flatten.hpp"]),
    ("curves", ["path"], ["bezier.hpp", "spline.hpp", "nurbs.hpp", "surface.hpp"]),
    ("raster", ["path"], ["raster.hpp", "round_stroke.hpp"]),
    ("stroke", ["path"], ["stroke.hpp"]),
    ("paint", ["geometry"], ["paint.hpp", "shader.hpp", "blend_mode.hpp"]),
    ("filter", ["paint"], ["filter.hpp"]),
    ("canvas", ["paint", "raster", "stroke"], ["canvas.hpp", "seamless.hpp"]),
    ("figures", ["canvas", "curves"], ["figures.hpp"]),
    ("text", ["canvas"], ["font.hpp", "font_database.hpp", "text.hpp", "shaping.hpp"]),
    ("json", ["core"], []),
    ("formats", ["text", "filter", "canvas", "json"], ["png.hpp", "image.hpp", "svg.hpp", "geojson.hpp"]),
    ("map", ["formats", "json", "canvas"], ["map.hpp", "projection.hpp", "tiles.hpp"]),
    # The umbrella header: includes every public C++ header (it has no folder under src/).
    ("umbrella", ["figures", "map"], ["casteljau.hpp"]),
    ("capi", ["umbrella"], ["casteljau.h", "casteljau_svg.h", "casteljau_map.h", "casteljau_text.h"]),
    ("cli", ["umbrella"], []),
]

# Stages that may include other stages' public headers only, never a header under src/<other>/.
PUBLIC_ONLY = {"cli"}

# Private headers (not installed) that a higher stage may include from a lower one; every other
# header under src/<stage>/ is private to its stage.
INTERNAL_INTERFACES = {
    "core/for_each_index.hpp",
    "core/large_buffer.hpp",
    "core/pixel_memory.hpp",
    "core/runtime_library.hpp",
    "core/simd_dispatch.hpp",
    "path/flatten_internal.hpp",
    "curves/curve_util.hpp",
    "paint/pixel_math.hpp",
    "paint/pipeline.hpp",
    "paint/pixmap_memory.hpp",
    "json/json_support.hpp",
    "formats/json_properties.hpp",  # JSON values as feature property values, for map's style reader
}

STAGES_FILE = "tools/check_layering.py"
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def allowed_stages():
    """Each stage's name -> the set of stages it may use (its own not included)."""
    allowed, order = {}, [name for name, _, _ in STAGES]
    for index, (name, uses, _) in enumerate(STAGES):
        reach = set()
        for used in uses:
            if used not in order[:index]:
                sys.exit(f"check_layering: stage {name} uses {used}, which is not listed before it")
            reach |= {used} | allowed[used]
        allowed[name] = reach
    return allowed


class Tree:
    """The files under src/ and include/casteljau/ and the stage each belongs to."""

    def __init__(self, root):
        self.root = root
        self.src = root / "src"
        self.include = root / "include"
        self.rank = {name: i for i, (name, _, _) in enumerate(STAGES)}
        self.public = {h: name for name, _, headers in STAGES for h in headers}

    def files(self):
        for top in (self.src, self.include / "casteljau"):
            yield from sorted(p for p in top.rglob("*") if p.is_file())

    def is_public(self, path):
        return path.is_relative_to(self.include)

    def stage_of(self, path):
        """The stage of a file, or None when it belongs to none."""
        if path.is_relative_to(self.include / "casteljau"):
            return self.public.get(path.relative_to(self.include / "casteljau").as_posix())
        if not path.is_relative_to(self.src):
            return None
        parts = path.relative_to(self.src).parts
        return parts[0] if len(parts) > 1 and parts[0] in self.rank else None

    def resolve(self, path, name):
        """The file `#include "name"` in `path` reads: its own folder first, then src/, include/."""
        for base in (path.parent, self.src, self.include):
            candidate = base / name
            if candidate.is_file():
                return candidate.resolve()
        return None

    def show(self, path):
        return path.relative_to(self.root).as_posix() if path.is_relative_to(self.root) else str(path)


def check_include(tree, allowed, path, stage, target):
    """Why `path` (of `stage`) may not include `target`, or None when it may."""
    target_stage = tree.stage_of(target)
    if target_stage is None:
        return "the included file belongs to no stage"
    if tree.is_public(path) and not tree.is_public(target):
        return "a public header may include only public headers"
    if target_stage == stage:
        return None
    if target_stage not in allowed[stage]:
        if tree.rank[target_stage] > tree.rank[stage]:
            return f"{target_stage} is above {stage}"
        return f"{stage} may not use {target_stage} (it may use: {', '.join(sorted(allowed[stage])) or 'nothing'})"
    if not tree.is_public(target):
        interface = target.relative_to(tree.src).as_posix()
        if stage in PUBLIC_ONLY:
            return f"{stage} may include other stages' public headers only"
        if interface not in INTERNAL_INTERFACES:
            return f"{interface} is private to {target_stage} (not an internal interface)"
    return None


def find_cycles(graph):
    """The include cycles of `graph` (file -> files it includes), each as a list of files."""
    cycles, state = [], {}
    for start in sorted(graph):
        if start in state:
            continue
        stack = [(start, iter(sorted(graph[start])))]
        state[start] = "open"
        while stack:
            node, children = stack[-1]
            child = next(children, None)
            if child is None:
                state[node] = "done"
                stack.pop()
            elif state.get(child) == "open":
                path = [n for n, _ in stack]
                cycles.append(path[path.index(child):] + [child])
            elif child not in state:
                state[child] = "open"
                stack.append((child, iter(sorted(graph.get(child, ())))))
    return cycles


def check(root):
    """Every offending include of the tree at `root`, as printable lines."""
    tree, allowed, problems, graph = Tree(root), allowed_stages(), [], {}
    for header in sorted(tree.public):
        if not (tree.include / "casteljau" / header).is_file():
            problems.append(f"{STAGES_FILE}: the table lists include/casteljau/{header}, which does not exist")
    for path in tree.files():
        path = path.resolve()
        stage = tree.stage_of(path)
        graph.setdefault(path, set())
        if stage is None:
            problems.append(f"{tree.show(path)}: belongs to no stage (add its stage or header to STAGES)")
            continue
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
        for number, line in enumerate(lines, 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            where = f"{tree.show(path)}:{number}: [{stage}] includes \"{match[1]}\""
            target = tree.resolve(path, match[1])
            if target is None:
                problems.append(f"{where}: not found in its folder, src/ or include/")
                continue
            graph[path].add(target)
            why = check_include(tree, allowed, path, stage, target)
            if why:
                problems.append(f"{where} [{tree.stage_of(target) or 'no stage'}]: {why}")
    for cycle in find_cycles(graph):
        problems.append("include cycle: " + " -> ".join(tree.show(p) for p in cycle))
    return problems



def cmake_table():
    """STAGES as CMake variables, for the build's stage targets: CASTELJAU_STAGES (lowest first),
    and per stage CASTELJAU_STAGE_<name>_USES (every stage it may use, lowest first) and
    CASTELJAU_STAGE_<name>_SEES (the src/ folders its include path shows: its own, and those of
    the stages it may use unless it may include public headers only)."""
    allowed, names = allowed_stages(), [name for name, _, _ in STAGES]
    lines = [f"# Written by {STAGES_FILE} --cmake from its table STAGES.",
             f"set(CASTELJAU_STAGES {' '.join(names)})"]
    for name in names:
        uses = [n for n in names if n in allowed[name]]
        sees = [name] + ([] if name in PUBLIC_ONLY else uses)
        lines.append(f"set(CASTELJAU_STAGE_{name}_USES {' '.join(uses)})")
        lines.append(f"set(CASTELJAU_STAGE_{name}_SEES {' '.join(sees)})")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent,
                        help="the repository (default: this script's parent folder's parent)")
    parser.add_argument("--cmake", action="store_true",
                        help="print the stage table as CMake variables instead of checking")
    args = parser.parse_args()
    if args.cmake:
        print(cmake_table(), end="")
        return 0
    root = args.root.resolve()
    if not (root / "src").is_dir() or not (root / "include" / "casteljau").is_dir():
        sys.exit(f"check_layering: {root} has no src/ and include/casteljau/")
    problems = check(root)
    for line in problems:
        print(line)
    if problems:
        print(f"check_layering: {len(problems)} include(s) break the layering (see STAGES in {STAGES_FILE})",
              file=sys.stderr)
        return 1
    print("check_layering: every include of src/ and include/casteljau/ follows the stages")
    return 0


if __name__ == "__main__":
    sys.exit(main())
