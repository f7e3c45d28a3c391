#!/usr/bin/env python3
"""bench/mapnik_compare.py: `casteljau map` and `casteljau tiles` side by side with Mapnik.

The same maps, drawn by both: a fill (#dddddd) and a 0.8 px stroke (#333333, round joins and caps;
another width with --stroke-width) of every country over a white background, equirectangular
(Mapnik: +proj=longlat), the
extent -180,-90,180,90 mapped onto W x W/2 pixels, at 4096 x 2048, 1024 x 512 and 256 x 128, for
countries-land-10km (GeoJSON) and Natural Earth 10m (world-atlas countries-10m.json, its
"countries" object; Mapnik's TopoJSON reader gets a copy holding that object only). Then a z0-z5
tile pyramid (Web Mercator, 256 px tiles, metatiles of 8 x 8 tiles with a 64 px buffer, as
`casteljau tiles` renders them; Mapnik renders the same metatiles with buffer_size 64 and crops
them). Mapnik leaves its own defaults otherwise (AGG, gamma 1; its fills show seams along shared
borders, casteljau's do not).

Per row, every time is CPU time (user + system, os.wait4) of one process, best of --rounds: the
benchmark machine is shared, so wall time mostly measures the scheduler.
  casteljau whole     the `casteljau map` (or `tiles`) process, one thread (--threads 1)
  casteljau draw+enc  that minus the same command drawing nothing (--fill none, no stroke): what
                      reading the file, fitting and starting the process cost is taken out
  Mapnik render+enc   mapnik.render + PNG encoding, timed inside the Python process
                      (time.process_time), the map and its data source already loaded
  Mapnik whole        the Python process: start, import mapnik, load, render, encode, write
  casteljau peak MB   peak resident set size of the casteljau process (ru_maxrss)
"before" rows draw every position (--simplify 0), the geometry as it was before the map stage
simplified it to the output's resolution; "after" rows use the default --simplify.

With --accuracy, build/bench/map_accuracy (cmake -DCASTELJAU_BUILD_BENCH=ON) measures the coverage
error of each row's rendering (map_accuracy draws it as `casteljau map` does, fill and stroke
apart, black on transparent) against the exact rendering of the original geometry (see
bench/map_accuracy.cpp) at each size: mean and max over all pixels, in 1/255. "before" is not
always 0: where a fill runs out of the rasterizer's exact-work budget, the whole image is
approximated there. It takes minutes (the reference is drawn window by window).

Usage: python3 bench/mapnik_compare.py [--rounds N] [--accuracy] [--only land|ne10m|tiles] [--casteljau BIN]
                                      [--stroke-width PX]   (default 0.8; wider strokes take the
                                      capsule and cell work that thin ones do not)
Needs bench/data (bench/setup_map_data.sh). Without the mapnik module (Debian: python3-mapnik,
for /usr/bin/python3) it prints why and exits 0.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "bench", "data")
FILL, STROKE, WIDTH, BACKGROUND = "#dddddd", "#333333", 0.8, "#ffffff"
SIZES = [4096, 1024, 256]
ZOOMS, TILE, METATILE, BUFFER = (0, 5), 256, 8, 64
MERCATOR = "+proj=merc +a=6378137 +b=6378137 +lat_ts=0 +lon_0=0 +x_0=0 +y_0=0 +k=1 +units=m +nadgrids=@null +no_defs"
LONGLAT = "+proj=longlat +datum=WGS84 +no_defs"
HALF = 20037508.342789244


def run(cmd):
    """Runs cmd; returns (CPU seconds of the child, peak RSS in MB, its standard output)."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        p = subprocess.Popen(cmd, stdout=out, stderr=err)
        _, status, ru = os.wait4(p.pid, 0)
        out.seek(0)
        err.seek(0)
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit("mapnik_compare: failed: %s\n%s" % (" ".join(cmd), err.read().decode(errors="replace")))
        return ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0, out.read().decode()


def best(rounds, cmd):
    """Best CPU time of `rounds` runs, their largest peak RSS, and the least first number each printed."""
    results = [run(cmd) for _ in range(rounds)]
    printed = [float(r[2].split()[0]) for r in results if r[2].strip()]
    return min(r[0] for r in results), max(r[1] for r in results), min(printed) if printed else None


# Both Mapnik programs' style: the fill and the round-joined, round-capped stroke, in `s`; the
# stroke width comes in as `stroke_width`.
MAPNIK_STYLE = "; ".join([
    "s = mapnik.Style()", "r = mapnik.Rule()",
    "poly = mapnik.PolygonSymbolizer()", "poly.fill = mapnik.Color(%r)" % FILL, "r.symbols.append(poly)",
    "line = mapnik.LineSymbolizer()", "line.stroke = mapnik.Color(%r)" % STROKE, "line.stroke_width = stroke_width",
    "line.stroke_linejoin = mapnik.stroke_linejoin.ROUND_JOIN",
    "line.stroke_linecap = mapnik.stroke_linecap.ROUND_CAP", "r.symbols.append(line)", "s.rules.append(r)"])

# The Mapnik side runs in a fresh /usr/bin/python3 process per measurement (its whole-process time
# is the point), from this program's text.
MAPNIK_MAP = textwrap.dedent("""
    import sys, time, mapnik
    kind, path, width, out, stroke_width = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4], float(sys.argv[5])
    m = mapnik.Map(width, width // 2, "%(longlat)s")
    m.background = mapnik.Color("%(background)s")
    %(style)s
    m.append_style("countries", s)
    layer = mapnik.Layer("countries", "%(longlat)s")
    layer.datasource = mapnik.Datasource(type=kind, file=path)
    layer.styles.append("countries")
    m.layers.append(layer)
    m.zoom_to_box(mapnik.Box2d(-180, -90, 180, 90))
    t0 = time.process_time()
    im = mapnik.Image(m.width, m.height)
    mapnik.render(m, im)
    png = im.tostring("png")
    t = time.process_time() - t0
    open(out, "wb").write(png)
    print(t)
""" % {"longlat": LONGLAT, "background": BACKGROUND, "style": MAPNIK_STYLE})

MAPNIK_TILES = textwrap.dedent("""
    import os, sys, time, mapnik
    kind, path, outdir, z0, z1, tile, meta, buf = sys.argv[1], sys.argv[2], sys.argv[3], *map(int, sys.argv[4:9])
    stroke_width = float(sys.argv[9])
    half = %(half)r
    %(style)s
    layer = mapnik.Layer("countries", "%(longlat)s")
    layer.datasource = mapnik.Datasource(type=kind, file=path)
    layer.styles.append("countries")
    t0 = time.process_time()
    tiles = 0
    for z in range(z0, z1 + 1):
        dim = 1 << z
        n = min(meta, dim)
        for y0 in range(0, dim, n):
            for x0 in range(0, dim, n):
                m = mapnik.Map(n * tile, n * tile, "%(mercator)s")
                m.background = mapnik.Color("%(background)s")
                m.append_style("countries", s)
                m.layers.append(layer)
                m.buffer_size = buf
                size = 2 * half / dim
                m.zoom_to_box(mapnik.Box2d(-half + x0 * size, half - (y0 + n) * size, -half + (x0 + n) * size, half - y0 * size))
                im = mapnik.Image(m.width, m.height)
                mapnik.render(m, im)
                for j in range(n):
                    for i in range(n):
                        png = im.view(i * tile, j * tile, tile, tile).tostring("png")
                        d = os.path.join(outdir, str(z), str(x0 + i))
                        os.makedirs(d, exist_ok=True)
                        open(os.path.join(d, "%%d.png" %% (y0 + j)), "wb").write(png)
                        tiles += 1
    print(time.process_time() - t0, tiles)
""" % {"half": HALF, "longlat": LONGLAT, "mercator": MERCATOR, "background": BACKGROUND,
       "style": MAPNIK_STYLE})


def have_mapnik():
    try:
        r = subprocess.run(["/usr/bin/python3", "-c", "import mapnik"], capture_output=True)
        return r.returncode == 0
    except OSError:
        return False


def casteljau_style(simplify, draw=True):
    style = ["--fill", FILL, "--stroke", STROKE, "--stroke-width", str(WIDTH)] if draw else ["--fill", "none"]
    return style + ["--background", BACKGROUND, "--line-join", "round", "--line-cap", "round", "--threads", "1"] + (
        ["--simplify", str(simplify)] if simplify is not None else [])


def accuracy(binary, path, layer, width):
    """map_accuracy's rows: {(picture, simplify text): (mean, max)} for the whole-image renders, with
    simplify 0 (before) and the default (after), against the exact rendering of the original."""
    cmd = [binary, path, "--width", str(width), "--window", str(32 if width <= 256 else 256), "--stroke-width", str(WIDTH)]
    if layer:
        cmd += ["--layer", layer]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    rows = {}
    for line in out.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 8 and cells[1] in ("fill", "stroke"):
            rows[(cells[1], "before" if cells[2] == "0" else "after")] = (float(cells[3]), int(cells[4]))
    return rows


def main():
    global WIDTH
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--accuracy", action="store_true")
    ap.add_argument("--only", choices=["land", "ne10m", "tiles"])
    ap.add_argument("--casteljau", default=os.path.join(ROOT, "build", "casteljau"))
    ap.add_argument("--stroke-width", type=float, default=WIDTH, help="stroke width in pixels (default 0.8)")
    args = ap.parse_args()
    WIDTH = args.stroke_width
    if not have_mapnik():
        print("mapnik_compare: skipped: the mapnik Python module is not installed for /usr/bin/python3 "
              "(Debian: apt-get install python3-mapnik)")
        return 0
    land = os.path.join(DATA, "countries-land-10km.geo.json")
    ne = os.path.join(DATA, "countries-10m.json")
    for f in (land, ne):
        if not os.path.exists(f):
            sys.exit("mapnik_compare: %s is missing; run bench/setup_map_data.sh first" % f)
    if not os.path.exists(args.casteljau):
        sys.exit("mapnik_compare: %s is missing; build the casteljau CLI first" % args.casteljau)
    acc_bin = os.path.join(ROOT, "build", "bench", "map_accuracy")
    if args.accuracy and not os.path.exists(acc_bin):
        sys.exit("mapnik_compare: --accuracy needs %s (cmake -DCASTELJAU_BUILD_BENCH=ON)" % acc_bin)
    work = tempfile.mkdtemp(prefix="mapnik_compare.")
    try:
        # Mapnik's TopoJSON reader draws every object: give it the countries only.
        topo = json.load(open(ne))
        topo["objects"] = {"countries": topo["objects"]["countries"]}
        ne_countries = os.path.join(work, "countries-10m-countries.json")
        json.dump(topo, open(ne_countries, "w"))
        datasets = [("countries-land-10km", land, "", "geojson", land), ("Natural Earth 10m", ne, "countries", "topojson", ne_countries)]
        if args.only == "land":
            datasets = datasets[:1]
        elif args.only == "ne10m":
            datasets = datasets[1:]
        elif args.only == "tiles":
            datasets = []
        print("casteljau: %s; Mapnik %s; %d rounds, best CPU time; machine: %d cores, load %.1f" % (
            args.casteljau, subprocess.run(["/usr/bin/python3", "-c", "import mapnik; print(mapnik.mapnik_version())"],
                                           capture_output=True, text=True).stdout.strip(),
            args.rounds, os.cpu_count(), os.getloadavg()[0]))
        print("| data | size | geometry | casteljau whole (ms) | casteljau draw+enc (ms) | Mapnik render+enc (ms) | Mapnik whole (ms) "
              "| casteljau peak MB | fill error mean/max (/255) | stroke error mean/max (/255) |")
        print("|---|---|---|---:|---:|---:|---:|---:|---|---|")
        for name, path, layer, kind, mapnik_path in datasets:
            for w in SIZES:
                out = os.path.join(work, "c.png")
                base = [args.casteljau, "map", path, "-o", out, "--width", str(w), "--height", str(w // 2),
                        "--bbox", "-180,-90,180,90"] + (["--layer", layer] if layer else [])
                t_mapnik_whole, _, t_mapnik = best(args.rounds, ["/usr/bin/python3", "-c", MAPNIK_MAP, kind, mapnik_path,
                                                                 str(w), os.path.join(work, "m.png"), str(WIDTH)])
                acc = accuracy(acc_bin, path, layer, w) if args.accuracy else {}
                for label, simplify in (("before", 0), ("after", None)):
                    t_whole, rss, _ = best(args.rounds, base + casteljau_style(simplify))
                    t_empty, _, _ = best(args.rounds, base + casteljau_style(simplify, draw=False))
                    err = lambda p: "%.3f / %d" % acc[(p, label)] if (p, label) in acc else "-"
                    print("| %s | %d x %d | %s | %.1f | %.1f | %.1f | %.1f | %.0f | %s | %s |" % (
                        name, w, w // 2, label, 1e3 * t_whole, 1e3 * (t_whole - t_empty), 1e3 * t_mapnik,
                        1e3 * t_mapnik_whole, rss,
                        err("fill"), err("stroke")))
                    sys.stdout.flush()
        if args.only in (None, "tiles"):
            tiles_rows(args, work, land)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


def tiles_rows(args, work, land):
    """The z0-z5 pyramid of countries-land-10km: both renderers, 1365 tiles each."""
    z = "%d-%d" % ZOOMS
    t_mapnik_whole, _, out = run(["/usr/bin/python3", "-c", MAPNIK_TILES, "geojson", land, os.path.join(work, "mt"),
                                  str(ZOOMS[0]), str(ZOOMS[1]), str(TILE), str(METATILE), str(BUFFER), str(WIDTH)])
    t_mapnik, n_tiles = float(out.split()[0]), int(out.split()[1])
    for label, simplify in (("before", 0), ("after", None)):
        def cmd(draw, d):
            return [args.casteljau, "tiles", land, "--zoom", z, "--metatile", str(METATILE), "--buffer", str(BUFFER), "-q",
                    "-o", os.path.join(work, d)] + casteljau_style(simplify, draw)
        shutil.rmtree(os.path.join(work, "ct"), ignore_errors=True)
        t_whole, rss, _ = run(cmd(True, "ct"))
        shutil.rmtree(os.path.join(work, "ce"), ignore_errors=True)
        t_empty, _, _ = run(cmd(False, "ce"))
        print("| countries-land-10km | tiles z%s (%d tiles) | %s | %.1f | %.1f | %.1f | %.1f | %.0f | - | - |" % (
            z, n_tiles, label, 1e3 * t_whole, 1e3 * (t_whole - t_empty), 1e3 * t_mapnik, 1e3 * t_mapnik_whole, rss))
        sys.stdout.flush()


if __name__ == "__main__":
    sys.exit(main())
