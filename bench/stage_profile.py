#!/usr/bin/env python3
"""Per-stage time of casteljau's glyph and map rasterization, next to FreeType's and AGG's.

Runs each workload under `perf record` (a software clock, so it also works where the machine has
no hardware counters), resolves every sample to its chain of inlined functions with `addr2line`,
and puts it in the pipeline stage of the innermost function a rule names. Each stage's share of
the timed samples, times the benchmark's own time per glyph (or per map), gives nanoseconds per
glyph (milliseconds per map) for each stage. The times per glyph and per map are the best of
several rounds of one process that runs the peers in turn (compare_glyphs, map_bench --profile
both), so that the columns of a table compare; the profiled runs give the shares only.

Workloads:
  glyphs: compare_glyphs at 12 and 256 px (DejaVu Sans, or --font), casteljau's font path
          (topology decided once per glyph, outside the timed part), its raw path (no verdict)
          and FreeType's FT_Outline_Render on the same outlines.
  map:    map_bench --profile render_map (casteljau's whole map stage, one thread) and
          --profile agg (AGG filling the same projected rings).

The build must carry debug information with release optimization, for example
  cmake -S . -B build-prof -DCMAKE_BUILD_TYPE=RelWithDebInfo \\
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O3 -g -DNDEBUG" -DCASTELJAU_BUILD_TESTS=OFF
  cmake --build build-prof --target compare_glyphs map_bench
Debian's libfreetype6 has no symbols for its internal functions; for FreeType's stages give
--freetype-lib a folder holding a libfreetype.so.6 of the same version built with -O2 -g (it is
loaded through LD_LIBRARY_PATH). Without it, FreeType's time is one row.

Usage: bench/stage_profile.py [--build build-prof] [--freetype-lib DIR] [--font FILE]
                              [--map bench/data/countries-land-10km.geo.json] [--only glyphs|map]
                              [--freq 5000] [--verbose] [--self-test]
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

# Stages in pipeline order. A sample goes to the stage of the innermost function (of its chain of
# inlined functions) that a rule matches.
STAGES = [
    "outline cache lookup",
    "fixed cost per shape (entry checks, limits, buffer set-up)",
    "transform",
    "flattening",
    "edge setup and clipping",
    "line integration (an edge's pieces per row or cell)",
    "cell management (finding, allocating, sorting cells)",
    "accumulation (area and cover into cells)",
    "overlap handling (winding sweep, overlap check, exact cells)",
    "sweep (cover sums into coverage)",
    "span output (clearing the output, writing rows)",
    "map: projection and paths",
    "map: compositing onto the image",
    "kernel (fresh pages)",
    "benchmark harness",
]
UNTIMED = "untimed (loading, preparation)"

# (stage, pattern). Patterns are searched in "function@file", where function has its template
# arguments and parameter lists removed, except for patterns starting with "full:", searched in
# the whole demangled name.
CASTELJAU_RULES = [
    ("overlap handling (winding sweep, overlap check, exact cells)", r"full:^(void )?casteljau::raster::Engine::walk<true"),
    ("overlap handling (winding sweep, overlap check, exact cells)",
     r"WindingSweep|Engine::classify|exact_cell|Engine::harmless|simple_run|closed_run|run_ends|run_edges|"
     r"Engine::gather|ExactScratch|Classifier|classify_topology|Engine::touch|PixelSet|inside_cells|"
     r"boundary_param|ends_alternate|Engine::add_cand|passes_through|"
     r"@.*/raster/(exact_cell|topology|winding_sweep)\.cpp"),
    ("accumulation (area and cover into cells)",
     r"RowVectorAccumulate|row_vector_accumulate|AccumulateFixed|AddPieceVector|AddRowPiece|raster::add_cell"),
    ("line integration (an edge's pieces per row or cell)",
     r"for_each_row|list_pieces|Engine::row_piece|Engine::walk|make_row_piece"),
    ("sweep (cover sums into coverage)",
     r"RowVectorEmit|row_vector_emit|ScanRows|scan_rows|ScanRange|ScanVectors|ScanBlocks|ApplyRule|StoreCoverage|"
     r"Engine::finish"),
    ("span output (clearing the output, writing rows)", r"SpanSink|BufferSink|memmove|memcpy|memset"),
    ("transform", r"Affine::apply|Affine::operator"),
    ("flattening", r"Flattener|flatten|Path::visit|@.*/path/flatten"),
    ("edge setup and clipping",
     r"Engine::push|Engine::admit|EdgeSink|PolylineSink|EdgeList|clip_edge|Engine::contour_end"),
    ("fixed cost per shape (entry checks, limits, buffer set-up)",
     r"Rasterizer::|Engine::begin|Engine::trim|current_limits|check_flatten_input|is_finite|control_bounds|"
     r"simd::chosen|row_vector_lanes|grow_zeroed|LargeBuffer"),
    ("map: compositing onto the image", r"Seamless|Compositor|composite|Pixmap::fill|blend"),
    ("map: projection and paths",
     r"MapProjection|MapData::bounds|project|feature_paths|FeaturePath|clip_to_frame|antimeridian|Path::add_polygon|"
     r"Path::move_to|Path::line_to|Path::close|@.*/map/"),
]
FREETYPE_RULES = [
    ("flattening", r"gray_render_conic|gray_render_cubic|gray_split_conic|gray_split_cubic|gray_conic_to|"
                   r"gray_cubic_to|FT_Outline_Decompose"),
    ("line integration (an edge's pieces per row or cell)", r"gray_render_line|gray_render_scanline"),
    ("cell management (finding, allocating, sorting cells)", r"gray_set_cell|gray_record_cell|gray_find_cell"),
    ("sweep (cover sums into coverage)", r"gray_sweep|gray_hline"),
    ("edge setup and clipping", r"gray_move_to|gray_line_to|gray_convert_glyph"),
    ("fixed cost per shape (entry checks, limits, buffer set-up)",
     r"FT_Outline_Render|gray_raster_render|FT_Outline_Get_CBox|gray_compute_cbox|setjmp|ft_smooth|"
     r"FT_Render_Glyph|gray_init_cells"),
    ("span output (clearing the output, writing rows)", r"memset|memcpy|memmove"),
]
AGG_RULES = [
    ("line integration (an edge's pieces per row or cell)", r"rasterizer_cells_aa::line|render_hline"),
    ("cell management (finding, allocating, sorting cells)",
     r"add_curr_cell|allocate_block|set_curr_cell|sort_cells|qsort_cells|rasterizer_cells_aa::reset|"
     r"scanline_cells|pod_"),
    ("sweep (cover sums into coverage)",
     r"sweep_scanline|calculate_alpha|rewind_scanlines|scanline_p8::|scanline_u8::|navigate_scanline"),
    ("edge setup and clipping",
     r"rasterizer_sl_clip|ras_conv|rasterizer_scanline_aa::(add_path|add_vertex|line_to|move_to|close_polygon|"
     r"edge)|path_storage|vertex_block_storage|path_base"),
    ("span output (clearing the output, writing rows)",
     r"render_scanline|blend_solid_hspan|blend_hline|renderer_base|pixfmt|memset|memcpy|copy_or_blend"),
]
COMMON_RULES = [
    ("benchmark harness", r"CasteljauFill|FreeTypeRenderer|AggMap|best_of|run_profile|^main@|thread_cpu|"
                          r"clock_gettime|__vdso"),
]
UNTIMED_RULES = [
    (UNTIMED, r"bench::Font|GlyphSet|glyph_set|load_glyph|FT_Load|FT_New|FT_Open|read_map_data|read_file|"
              r"split_ring|simdjson|TT_Load|@.*/src/(truetype|sfnt|cff|psaux|pshinter)/|@.*/src/base/ftobjs|"
              r"^_dl_|^dl_|do_lookup|check_match|_dl_relocate|strchr|^init_|__libc_start|_start@"),
]
SKIP_FRAME = re.compile(r"^(std::|__gnu_cxx::|hwy::|operator new|operator delete)")


def strip_args(name):
    """casteljau::Path::visit<...>(...) const -> casteljau::Path::visit"""
    out, depth = [], 0
    for ch in name:
        if ch in "<(":
            depth += 1
        elif ch in ">)":
            depth = max(0, depth - 1)
        elif depth == 0:
            out.append(ch)
    return re.sub(r"\s*const$", "", "".join(out)).strip()


def compile_rules(rules):
    out = []
    for stage, pat in rules:
        full = pat.startswith("full:")
        out.append((stage, full, re.compile(pat[5:] if full else pat)))
    return out


def classify(frames, rules):
    """frames: [(demangled function, file)], innermost first."""

    def match(func, path):
        key = strip_args(func) + "@" + path
        return next((stage for stage, full, rx in rules if rx.search(func if full else key)), None)

    # The innermost frame a rule names, past the standard library's; for a chain of those only,
    # the outermost frame that one names.
    for func, path in frames:
        if not SKIP_FRAME.search(func):
            stage = match(func, path)
            if stage:
                return stage
    return next(filter(None, (match(func, path) for func, path in reversed(frames))), None)


def symbol_table(dso):
    """Mangled symbol -> address, from the file's symbol table (and dynamic one)."""
    table = {}
    for flag in ([], ["-D"]):
        res = subprocess.run(["nm", "--defined-only", *flag, dso], capture_output=True, text=True)
        for line in res.stdout.splitlines():
            parts = line.split()
            if len(parts) == 3:
                table.setdefault(parts[2], int(parts[0], 16))
    return table


def resolve(dso, addrs):
    """address -> [(function, file)] innermost first, from addr2line."""
    if not addrs:
        return {}
    res = subprocess.run(["addr2line", "-a", "-f", "-i", "-C", "-e", dso],
                         input="\n".join("%x" % a for a in addrs), capture_output=True, text=True)
    out, cur, lines = {}, None, res.stdout.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("0x"):
            cur = int(line, 16)
            out[cur] = []
            i += 1
            continue
        func = line
        path = lines[i + 1] if i + 1 < len(lines) else "??"
        out[cur].append((func, path.split(" ")[0].rsplit(":", 1)[0]))
        i += 2
    return out


SAMPLE = re.compile(r"^\s*[0-9a-f]+\s+(\S+?)\+0x([0-9a-f]+)\s+\((.*)\)\s*$")
UNKNOWN = re.compile(r"^\s*[0-9a-f]+\s+(\S+)\s+\((.*)\)\s*$")


def profile(cmd, env, freq, rules, verbose):
    """Runs cmd under perf; returns (stage -> samples, benchmark stdout)."""
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, "perf.data")
        run = subprocess.run(["perf", "record", "-q", "-e", "cpu-clock", "-F", str(freq), "-o", data, "--", *cmd],
                             env=env, capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit("stage_profile: error: %s failed: %s" % (" ".join(cmd), run.stderr.strip()[-400:]))
        script = subprocess.run(["perf", "script", "--no-demangle", "-i", data, "-F", "ip,sym,symoff,dso"],
                                capture_output=True, text=True).stdout
    counts = collections.Counter()
    for line in script.splitlines():
        m = SAMPLE.match(line)
        if m:
            counts[(m.group(3), m.group(1), int(m.group(2), 16))] += 1
            continue
        m = UNKNOWN.match(line)
        if m:
            counts[(m.group(2), m.group(1), None)] += 1
    by_dso = collections.defaultdict(set)
    tables = {}
    for dso, sym, off in counts:
        if off is not None and not dso.startswith("["):
            if dso not in tables:
                tables[dso] = symbol_table(dso)
            if sym in tables[dso]:
                by_dso[dso].add(tables[dso][sym] + off)
    chains = {dso: resolve(dso, sorted(addrs)) for dso, addrs in by_dso.items()}

    def frames_of(dso, sym, off):
        addr = tables.get(dso, {}).get(sym)
        frames = chains.get(dso, {}).get(addr + off) if addr is not None and off is not None else None
        return frames if frames and frames[0][0] != "??" else None

    # Samples without debug information (libc, the loader) are named by their symbol alone.
    bare = sorted({sym for (dso, sym, off) in counts if not dso.startswith("[kernel") and not frames_of(dso, sym, off)})
    names = subprocess.run(["c++filt"], input="\n".join(bare), capture_output=True, text=True).stdout.splitlines()
    demangled = dict(zip(bare, names)) if len(names) == len(bare) else {}
    stages, unmatched = collections.Counter(), collections.Counter()
    for (dso, sym, off), n in counts.items():
        if dso.startswith("[kernel"):
            stages["kernel (fresh pages)"] += n
            continue
        frames = frames_of(dso, sym, off) or [(demangled.get(sym, sym), dso)]
        stage = classify(frames, rules)
        if stage is None:
            unmatched[strip_args(frames[-1][0]) + " (" + os.path.basename(frames[0][1]) + ")"] += n
            stage = "other"
        stages[stage] += n
    if verbose:
        for name, n in unmatched.most_common(15):
            print("  unmatched %6d  %s" % (n, name), file=sys.stderr)
    return stages, run.stdout


def glyph_times(exe, sizes, names, font, env):
    """ns per glyph for each (size, renderer), all timed in one compare_glyphs process."""
    cmd = [exe, "--no-check", "--sizes", ",".join(map(str, sizes)), "--runs", "5", "--only", ",".join(names)]
    run = subprocess.run(cmd + (["--font", font] if font else []), env=env, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("stage_profile: error: compare_glyphs failed: " + run.stderr.strip()[-400:])
    header = re.search(r"^\| px \|(.*)\|$", run.stdout, re.M)
    if not header:
        sys.exit("stage_profile: error: no throughput table in compare_glyphs' output")
    cols = [c.strip() for c in header.group(1).split("|")]
    times = {}
    for size in sizes:
        m = re.search(r"^\|\s*%d\s*\|(.*)\|$" % size, run.stdout, re.M)
        if not m:
            sys.exit("stage_profile: error: no %d px row in compare_glyphs' output" % size)
        for col, rate in zip(cols, m.group(1).split("|")):
            times[(size, re.sub(r" \(.*\)$", "", col) if col.startswith("FreeType") else col)] = 1e6 / float(rate)
    return times


def map_times(exe, path, env):
    """ms per map for render_map and AGG, timed in turn in one map_bench process."""
    run = subprocess.run([exe, path, "--profile", "both", "--rounds", "15"], env=env, capture_output=True,
                         text=True)
    found = dict(re.findall(r"profile (\S+) fill: best of \d+ rounds ([0-9.]+) ms", run.stdout))
    if run.returncode != 0 or set(found) != {"render_map", "agg"}:
        sys.exit("stage_profile: error: map_bench --profile both failed: " + (run.stderr + run.stdout)[-400:])
    return {k: float(v) for k, v in found.items()}


def table(title, unit, columns):
    """columns: [(name, stage counter, total time)]. Prints one markdown table."""
    print("\n%s (%s; share of the timed samples in brackets)\n" % (title, unit))
    print("| stage | " + " | ".join(name for name, _, _ in columns) + " |")
    print("|---|" + "---:|" * len(columns))
    rows = STAGES + ["other"]
    for stage in rows:
        cells, any_value = [], False
        for _, counts, total in columns:
            timed = sum(n for s, n in counts.items() if s != UNTIMED)
            n = counts.get(stage, 0)
            if n and timed:
                share = n / timed
                any_value = any_value or share >= 0.0005
                cells.append("%.3g (%.1f %%)" % (share * total, 100 * share))
            else:
                cells.append("-")
        if any_value:
            print("| %s | %s |" % (stage, " | ".join(cells)))
    print("| **total** | " + " | ".join("**%.3g**" % total for _, _, total in columns) + " |")
    samples = ", ".join("%s %d" % (name, sum(n for s, n in c.items() if s != UNTIMED)) for name, c, _ in columns)
    print("\nTimed samples: %s." % samples)


# Inlined chains (innermost first) as addr2line names them, and the stage each must land in: what
# --self-test checks, so that a rule that stops matching the code it names is caught by ctest.
SELF_TEST = [
    ("cas", [("casteljau::raster::floor_nn(double)", "engine.hpp"),
             ("casteljau::raster::Engine::list_pieces(double, double, double, double)::{lambda(int, double, double,"
              " double, double)#1}::operator()(int, double, double, double, double) const", "engine.hpp"),
             ("casteljau::raster::Engine::push(double, double, double, double)", "engine.hpp")],
     "line integration (an edge's pieces per row or cell)"),
    ("cas", [("std::min<double>(double const&, double const&)", "stl_algobase.h"),
             ("casteljau::raster::Engine::admit(double, double&, double, double&)", "engine.hpp")],
     "edge setup and clipping"),
    ("cas", [("void casteljau::raster::Engine::walk<true, double>(double, double, double, double)", "engine.hpp")],
     "overlap handling (winding sweep, overlap check, exact cells)"),
    ("cas", [("void casteljau::raster::add_cell<float>(float*, int, double, double, double)", "engine.hpp"),
             ("void casteljau::raster::Engine::walk<false, float>(double, double, double, double)", "engine.hpp")],
     "accumulation (area and cover into cells)"),
    ("cas", [("hwy::N_AVX3::Add(hwy::N_AVX3::Vec256<float>, hwy::N_AVX3::Vec256<float>)", "x86_256-inl.h"),
             ("casteljau::raster::N_AVX3::ScanRange<float>(float*, unsigned char*, int, int, float, "
              "casteljau::FillRule)", "coverage.cpp")],
     "sweep (cover sums into coverage)"),
    ("cas", [("casteljau::raster::WindingSweep::first_crossing(...) const", "winding_sweep.cpp")],
     "overlap handling (winding sweep, overlap check, exact cells)"),
    ("cas", [("casteljau::Affine::apply(casteljau::Point) const", "geometry.hpp"),
             ("void casteljau::Path::visit<casteljau::flatten_detail::Flattener<...>&>(...) const", "path.hpp")],
     "transform"),
    ("cas", [("__memmove_avx512_unaligned_erms", "libc.so.6")], "span output (clearing the output, writing rows)"),
    ("font", [("casteljau::(anonymous namespace)::Classifier::run()", "topology.cpp")], UNTIMED),
    ("ft", [("gray_set_cell", "ftgrays.c"), ("gray_render_line", "ftgrays.c")],
     "cell management (finding, allocating, sorting cells)"),
    ("ft", [("gray_render_line", "ftgrays.c")], "line integration (an edge's pieces per row or cell)"),
    ("ft", [("gray_hline", "ftgrays.c"), ("gray_sweep", "ftgrays.c")], "sweep (cover sums into coverage)"),
    ("ft", [("gray_split_conic", "ftgrays.c"), ("gray_render_conic", "ftgrays.c")], "flattening"),
    ("ft", [("load_truetype_glyph", "/tmp/ft/src/truetype/ttgload.c")], UNTIMED),
    ("agg", [("agg::rasterizer_cells_aa<agg::cell_aa>::sort_cells()", "agg_rasterizer_cells_aa.h")],
     "cell management (finding, allocating, sorting cells)"),
    ("agg", [("bool agg::rasterizer_scanline_aa<...>::sweep_scanline<agg::scanline_p8>(agg::scanline_p8&)",
              "agg_rasterizer_scanline_aa.h")], "sweep (cover sums into coverage)"),
]


def self_test(rule_sets):
    failures = 0
    for key, frames, want in SELF_TEST:
        got = classify(frames, rule_sets[key])
        if got != want:
            failures += 1
            print("stage_profile: self-test: %s went to %r, not %r" % (frames[0][0], got, want), file=sys.stderr)
    print("stage_profile: self-test: %d of %d chains in their stage" % (len(SELF_TEST) - failures, len(SELF_TEST)))
    return 1 if failures else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build-prof")
    ap.add_argument("--freetype-lib", default=None)
    ap.add_argument("--font", default=None)
    ap.add_argument("--map", default="bench/data/countries-land-10km.geo.json")
    ap.add_argument("--only", choices=["glyphs", "map"], default=None)
    ap.add_argument("--freq", type=int, default=5000)
    ap.add_argument("--passes", type=int, default=0, help="passes over the glyph set (default: by size)")
    ap.add_argument("--verbose", action="store_true")
    ap.add_argument("--self-test", action="store_true", help="check the rules on known chains, run nothing")
    args = ap.parse_args()
    cas = compile_rules(COMMON_RULES + UNTIMED_RULES + CASTELJAU_RULES)
    font_path = compile_rules(COMMON_RULES + UNTIMED_RULES + [(UNTIMED, r"Classifier|classify_topology")] +
                              CASTELJAU_RULES)
    ft = compile_rules(COMMON_RULES + UNTIMED_RULES + FREETYPE_RULES)
    agg = compile_rules(COMMON_RULES + UNTIMED_RULES + AGG_RULES)
    if args.self_test:
        sys.exit(self_test({"cas": cas, "font": font_path, "ft": ft, "agg": agg}))
    env = dict(os.environ)
    ft_env = dict(env)
    if args.freetype_lib:
        ft_env["LD_LIBRARY_PATH"] = args.freetype_lib
    if args.only in (None, "glyphs"):
        exe = os.path.join(args.build, "bench", "compare_glyphs")
        names = ["casteljau (font path)", "casteljau", "FreeType"]
        times = glyph_times(exe, [12, 256], names, args.font, ft_env)
        for size, passes in ((12, 1000), (256, 50)):
            passes = args.passes or passes
            columns = []
            for name, rules, e in zip(names, (font_path, cas, ft), (env, env, ft_env)):
                cmd = [exe, "--no-check", "--sizes", str(size), "--runs", "3", "--passes", str(passes),
                       "--only", name] + (["--font", args.font] if args.font else [])
                if args.verbose:
                    print("%s, %d px:" % (name, size), file=sys.stderr)
                counts, _ = profile(cmd, e, args.freq, rules, args.verbose)
                label = {"casteljau": "casteljau (raw path)"}.get(name, name)
                columns.append((label, counts, times[(size, name)]))
            table("Glyphs at %d px" % size, "ns per glyph", columns)
    if args.only in (None, "map"):
        exe = os.path.join(args.build, "bench", "map_bench")
        times = map_times(exe, args.map, env)
        columns = []
        for name, rules, label in (("render_map", cas, "casteljau render_map"), ("agg", agg, "AGG")):
            cmd = [exe, args.map, "--profile", name, "--rounds", "40"]
            if args.verbose:
                print("%s:" % name, file=sys.stderr)
            counts, _ = profile(cmd, env, args.freq, rules, args.verbose)
            columns.append((label, counts, times[name]))
        table("World map fill, one thread", "ms per map", columns)

if __name__ == "__main__":
    main()
