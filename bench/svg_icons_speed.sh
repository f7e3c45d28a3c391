#!/usr/bin/env bash
# SVG icons, file for file against rsvg-convert: every icon of the npm package feather-icons
# 4.29.1 (287 stroked 24 x 24 icons, MIT licence; installed into bench/data/ on first use, never
# needed by the tests) rendered 96 px wide by `casteljau svg` and by `rsvg-convert`, one process
# per file as a user runs them, the two alternating file by file, ROUNDS times. For each file the
# median over rounds of each program's CPU time (user + system); prints the median
# ratio casteljau / rsvg-convert over the files, the share of files where casteljau is slower, and
# the totals.
# Usage: bench/svg_icons_speed.sh [BUILD_DIR] [ROUNDS]      (default build, 5)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
rounds=${2:-5}
command -v rsvg-convert > /dev/null || { echo "rsvg-convert is not installed"; exit 77; }
icons=$root/bench/data/feather-icons
if [ ! -d "$icons" ]; then
  work=$(mktemp -d)
  (cd "$work" && npm install --silent --no-save feather-icons@4.29.1 > /dev/null)
  mkdir -p "$icons"
  cp "$work"/node_modules/feather-icons/dist/icons/*.svg "$icons/"
  rm -rf "$work"
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# CPU time of each child process from the kernel's rusage (microseconds; GNU time rounds to 10 ms).
python3 - "$build/casteljau" "$icons" "$out" "$rounds" <<'PY'
import os, resource, statistics as st, subprocess, sys
casteljau, icons, out, rounds = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
files = sorted(f for f in os.listdir(icons) if f.endswith(".svg"))
def cpu(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
times = {f: ([], []) for f in files}
for _ in range(rounds):
    for f in files:
        path = os.path.join(icons, f)
        times[f][0].append(cpu([casteljau, "svg", path, "-w", "96", "-o", os.path.join(out, "c.png")]))
        times[f][1].append(cpu(["rsvg-convert", "-w", "96", path, "-o", os.path.join(out, "r.png")]))
ratios, slower, tc, tr, names = [], 0, 0.0, 0.0, []
for f in files:
    c, r = st.median(times[f][0]), st.median(times[f][1])
    ratios.append(c / r); slower += c > r; tc += c; tr += r
    if c > r: names.append(f"{f} ({c * 1000:.2f} vs {r * 1000:.2f} ms)")
n = len(files)
print(f"{n} icons, 96 px, {rounds} rounds; median CPU per file: casteljau {tc / n * 1000:.2f} ms, rsvg-convert {tr / n * 1000:.2f} ms")
print(f"casteljau / rsvg-convert per file: median {st.median(ratios):.2f}, worst {max(ratios):.2f}; casteljau slower on {slower} of {n}")
if names: print("slower: " + ", ".join(names))
PY
