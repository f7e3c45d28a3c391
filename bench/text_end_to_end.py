#!/usr/bin/env python3
"""Whole-process CPU time of `casteljau text` against hb-view, the commands alternating.

Each case runs both commands `--runs` times after one warm-up each (which also leaves the font
fallback answers in casteljau's cache folder, as a user's earlier run would), alternating, and
reports the median of user + system CPU time of each finished process. Cases:
  latin   a 300-character Latin line in DejaVu Sans, against hb-view with the same font;
  mixed   a 300-character line of Latin, emoji, CJK and Greek (casteljau: DejaVu Sans and system
          fallback to Noto Color Emoji and Noto Sans CJK), against hb-view with Noto Sans CJK
          alone (its emoji come out as .notdef boxes);
  letter  the letter A, against hb-view (what is left is process start-up);
  nofall  the Latin line with and without --no-system-fonts (casteljau against itself).
Skips with a message when hb-view or a font is missing.

  python3 bench/text_end_to_end.py [--casteljau build/casteljau] [--runs 41] [--only mixed]
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEJAVU = os.path.join(ROOT, "fonts", "DejaVuSans.ttf")
CJK = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc"
LATIN = ("The quick brown fox jumps over the lazy dog. " * 7)[:300]
MIXED = ("Hello 👋 world ✓ 日本語 Ελληνικά " * 20)[:300]


def cpu_seconds(cmd):
    """Runs `cmd` with its output discarded; returns its user + system CPU time."""
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read().decode(errors="replace")
    proc.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"text_end_to_end: {' '.join(cmd[:2])} failed: {err.strip()}")
    return usage.ru_utime + usage.ru_stime


def compare(name, ours, theirs, peer, runs):
    cpu_seconds(ours)
    cpu_seconds(theirs)
    a, b = [], []
    for _ in range(runs):
        a.append(cpu_seconds(ours))
        b.append(cpu_seconds(theirs))
    ma, mb = statistics.median(a), statistics.median(b)
    print(f"{name:8s} casteljau {ma * 1e3:6.1f} ms   {peer} {mb * 1e3:6.1f} ms   "
          f"speed {mb / ma:.2f}x {peer}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--casteljau", default=os.path.join(ROOT, "build", "casteljau"))
    ap.add_argument("--runs", type=int, default=41)
    ap.add_argument("--only", choices=["latin", "mixed", "letter", "nofall"])
    args = ap.parse_args()
    hb = shutil.which("hb-view")
    if not hb:
        print("text_end_to_end: skipped, hb-view is not installed (Debian: libharfbuzz-bin)")
        return
    out = tempfile.mkdtemp(prefix="text_e2e_")
    cj = lambda text, *extra: [args.casteljau, "text", text, "--font", DEJAVU, "--size", "48",
                               "-o", os.path.join(out, "cj.png"), *extra]
    hbv = lambda font, text: [hb, font, "--font-size=48", "-o", os.path.join(out, "hb.png"),
                              "--output-format=png", text]
    cases = {
        "latin": lambda: compare("latin", cj(LATIN), hbv(DEJAVU, LATIN), "hb-view", args.runs),
        "mixed": lambda: (compare("mixed", cj(MIXED), hbv(CJK, MIXED), "hb-view", args.runs)
                          if os.path.exists(CJK) else
                          print("mixed    skipped: Noto Sans CJK is not installed (fonts-noto-cjk)")),
        "letter": lambda: compare("letter", cj("A"), hbv(DEJAVU, "A"), "hb-view", args.runs),
        "nofall": lambda: compare("nofall", cj(LATIN), cj(LATIN, "--no-system-fonts"),
                                  "--no-system-fonts", args.runs),
    }
    try:
        for name, run in cases.items():
            if args.only in (None, name):
                run()
    finally:
        shutil.rmtree(out, ignore_errors=True)


if __name__ == "__main__":
    main()
