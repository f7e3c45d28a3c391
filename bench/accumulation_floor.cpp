// bench/accumulation_floor.cpp: how fast can the accumulation step alone be?
//
// A speed target of 1.5x FreeType's smooth rasterizer on the glyph set of compare_glyphs sets a
// budget per glyph. This program measures lower bounds for two designs that casteljau could switch
// to, on the same glyphs, in the same process as FreeType and casteljau:
//
//   FreeType          FT_Outline_Render of the outline: everything (flattening, cells, sweep, spans)
//   budget            FreeType's time / 1.5: what casteljau may spend on everything to be 1.5x as fast
//   flatten           the fill's own flattener (flatten_into, area-balanced, into the fill's batch
//                     sink, as Rasterizer::fill runs them), its polylines handed on and dropped,
//                     nothing else: what any chord-based design pays first
//   casteljau         Rasterizer::fill of the *already flattened* polygon (exact overlaps on; no
//                     flattening timed), and the same with exact overlaps off
//   dense float       font-rs's design: every edge walked through a dense float buffer (cover/area),
//                     then one prefix sum per row into 8-bit coverage (nonzero)
//   row vector        the design casteljau's fill uses for narrow shapes without the overlap check
//                     (RowPiece in src/raster/raster_internal.hpp): each piece of an edge inside one
//                     pixel row adds its exact area to every pixel of the row in SIMD vectors
//                     (Highway, runtime dispatch), so there is no per-cell loop and no prefix sum;
//                     rows are then mapped to 8-bit coverage. Here splitting and area are one pass
//                     with no piece records (make_row_piece and AddRowPiece, the library's own,
//                     applied at once): this is the design's floor
//
// The two floors do strictly less than casteljau: no flattening, no clipping, no overlap check,
// no span sink, the edges already converted to float, nonzero only. So their time is a lower
// bound on what a rasterizer of that design needs for this glyph set. Both are checked against
// casteljau (exact overlaps off, same polygons): a floor that disagrees by more than 1/255 at any
// pixel makes the program exit 1 (this is what the ctest smoke test checks), so a broken floor
// cannot report a fast time.
//
// Usage: accumulation_floor [--quick] [--runs R] [--min-time S] [--sizes 12,24,...] [--tolerance PX]
//                           [--font FILE]
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "accumulation_floor.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/row_vector-inl.h"  // the library's row-vector kernel, for every target
#include "core/simd_dispatch.hpp"   // the library's dispatch (no libhwy)

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "casteljau/flatten.hpp"
#include "casteljau/raster.hpp"
#include "glyph_set.hpp"
#include "path/flatten_internal.hpp"
#include "raster/edge_builder.hpp"
#include "timer.hpp"

#ifndef ACCUMULATION_FLOOR_SHARED
#define ACCUMULATION_FLOOR_SHARED
namespace floorbench {
// One edge of a flattened glyph, in pixels of the glyph's box (y down).
struct Seg {
    float x0, y0, x1, y1;
};
// One glyph's edges and box size, and scratch large enough for the box.
struct Job {
    const Seg* segs;
    std::size_t n;
    int w, h;
    float* acc;         // `stride` floats per row, zero on entry and on return
    std::uint8_t* out;  // row vector: `stride` bytes per row; dense float: w bytes per row
    int stride;         // row vector: w rounded up to whole granules (row_vector_stride); dense float: w + 2
};
}  // namespace floorbench
#endif

HWY_BEFORE_NAMESPACE();
namespace floorbench {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Calls f(row, x at the piece's top, x at its bottom, signed height) for each piece of `e` inside
// one pixel row of [0, h), top to bottom (the sign: +1 for an edge going down, -1 going up).
template <class F>
HWY_INLINE void ForEachRowPiece(const Seg& e, int h, F&& f) {
    float x0 = e.x0, y0 = e.y0, x1 = e.x1, y1 = e.y1;
    if (y0 == y1) return;
    float dir = 1.0f;
    if (y0 > y1) {
        dir = -1.0f;
        std::swap(x0, x1);
        std::swap(y0, y1);
    }
    const float dxdy = (x1 - x0) / (y1 - y0);
    float x = x0;
    const int ys = static_cast<int>(y0), ye = std::min(h, static_cast<int>(std::ceil(y1)));
    for (int y = ys; y < ye; ++y) {
        const float dy = std::min(static_cast<float>(y + 1), y1) - std::max(static_cast<float>(y), y0);
        const float xn = y + 1 >= y1 ? x1 : x + dxdy * dy;
        f(y, x, xn, dy * dir);
        x = xn;
    }
}

// font-rs's accumulation: cover/area into a dense float buffer of (w + 2) x h cells, then one
// running sum per glyph into 8-bit nonzero coverage (the buffer is cleared as it is read). Compiled
// per SIMD target like the rest, so the compiler may vectorise it where it can.
void DenseFloatImpl(const Job& job) {
    const Seg* segs = job.segs;
    const int w = job.w, h = job.h;
    float* acc = job.acc;
    std::uint8_t* out = job.out;
    const int stride = w + 2;
    for (std::size_t k = 0; k < job.n; ++k) {
        ForEachRowPiece(segs[k], h, [&](int y, float x, float xn, float dd) {
            float* a = acc + static_cast<std::size_t>(y) * static_cast<std::size_t>(stride);
            const float xa = std::min(x, xn), xb = std::max(x, xn);
            const int i0 = static_cast<int>(xa);
            const int i1 = static_cast<int>(std::ceil(xb));
            if (i1 <= i0 + 1) {
                const float xm = 0.5f * (x + xn) - static_cast<float>(i0);
                a[i0] += dd - dd * xm;
                a[i0 + 1] += dd * xm;
                return;
            }
            const float s = 1.0f / (xb - xa);
            const float f0 = xa - static_cast<float>(i0), f1 = xb - static_cast<float>(i1) + 1.0f;
            const float g0 = 1.0f - f0;
            const float am = 0.5f * s * g0 * g0;
            a[i0] += dd * am;
            if (i1 == i0 + 2) {
                a[i0 + 1] += dd * (1.0f - am - 0.5f * s * f1 * f1);
            } else {
                const float a1 = s * (1.5f - f0);
                a[i0 + 1] += dd * (a1 - am);
                for (int i = i0 + 2; i < i1 - 1; ++i) a[i] += dd * s;
                const float a2 = a1 + static_cast<float>(i1 - i0 - 3) * s;
                a[i1 - 1] += dd * (1.0f - a2 - 0.5f * s * f1 * f1);
            }
            a[i1] += dd * 0.5f * s * f1 * f1;
        });
    }
    for (int y = 0; y < h; ++y) {
        float* a = acc + static_cast<std::size_t>(y) * static_cast<std::size_t>(w + 2);
        std::uint8_t* o = out + static_cast<std::size_t>(y) * static_cast<std::size_t>(w);
        float sum = 0;
        for (int x = 0; x < w + 2; ++x) {
            sum += a[x];
            a[x] = 0;
            if (x < w) o[x] = static_cast<std::uint8_t>(std::min(std::fabs(sum), 1.0f) * 255.0f + 0.5f);
        }
    }
}

// Rows of whole granules, as the library's (raster_internal.hpp).
int StrideImpl(int w) {
    const int n = casteljau::raster::HWY_NAMESPACE::GranuleLanes();
    return (w + n - 1) / n * n;
}

// The piece of an edge inside row r, from x = xa to x = xb, with signed height dy, adds to pixel c
// the integral over the piece's height of clamp(c + 1 - x, 0, 1): the part of the piece inside
// [c, c + 1] contributes its height times the distance of its mid point to the pixel's right side,
// the part left of the pixel its whole height. Per pixel (SIMD lanes): with u0 = max(xl, c),
// u1 = min(xr, c + 1),
//     dy / (xr - xl) * (max(u1 - u0, 0) * (c + 1 - (u0 + u1) / 2) + max(min(xr, c) - xl, 0)).
// A (nearly) vertical piece is widened to 1e-4 px around its mid point (an area change below
// 1e-4 of a pixel).
void RowVectorImpl(const Job& job) {
    const hn::ScalableTag<float> d;
    for (std::size_t k = 0; k < job.n; ++k) {
        ForEachRowPiece(job.segs[k], job.h, [&](int r, float xa, float xb, float dy) {
            // The library's piece and kernel, applied at once (no piece records).
            const casteljau::raster::RowPiece p =
                casteljau::raster::make_row_piece(r, std::min(xa, xb), std::max(xa, xb), dy);
            casteljau::raster::HWY_NAMESPACE::AddRowPiece(
                d, p, job.acc + static_cast<std::size_t>(r) * static_cast<std::size_t>(job.stride), job.stride);
        });
    }
    // Nonzero rule, 8-bit, and clear the rows.
    for (int r = 0; r < job.h; ++r) {
        float* row = job.acc + static_cast<std::size_t>(r) * static_cast<std::size_t>(job.stride);
        std::uint8_t* o = job.out + static_cast<std::size_t>(r) * static_cast<std::size_t>(job.stride);
        casteljau::raster::HWY_NAMESPACE::ForRowVectors(d, 0, job.stride, [&](auto dv, int i) {
            const hn::Rebind<std::int32_t, decltype(dv)> di;
            const hn::Rebind<std::uint8_t, decltype(dv)> du8;
            const auto v = hn::Min(hn::Abs(hn::LoadU(dv, row + i)), hn::Set(dv, 1.0f));
            hn::StoreU(hn::Zero(dv), dv, row + i);
            hn::StoreU(hn::DemoteTo(du8, hn::ConvertTo(di, hn::MulAdd(v, hn::Set(dv, 255.0f), hn::Set(dv, 0.5f)))), du8,
                       o + i);
        });
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace floorbench
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace floorbench {
CASTELJAU_SIMD_EXPORT(StrideImpl);
CASTELJAU_SIMD_EXPORT(RowVectorImpl);
CASTELJAU_SIMD_EXPORT(DenseFloatImpl);

int row_vector_stride(int w) { return CASTELJAU_SIMD_DISPATCH(StrideImpl)(w); }
void row_vector(const Job& job) { CASTELJAU_SIMD_DISPATCH(RowVectorImpl)(job); }
void dense_float(const Job& job) { CASTELJAU_SIMD_DISPATCH(DenseFloatImpl)(job); }

}  // namespace floorbench

namespace {

using floorbench::Seg;

struct Options : bench::CommonOptions {
    double tolerance = casteljau::kDefaultTolerance;
    std::string font = CASTELJAU_BENCH_FONT;
};

[[noreturn]] void usage(const char* msg) {
    std::fprintf(stderr,
                 "accumulation_floor: %s\nusage: accumulation_floor [--quick] [--runs R] [--min-time S] [--sizes "
                 "12,24,...] [--tolerance PX] [--font FILE]\n",
                 msg);
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (o.parse_common(argc, argv, i, usage)) continue;
        if (a == "--tolerance") {
            if (i + 1 >= argc) usage("missing value after --tolerance");
            o.tolerance = std::atof(argv[++i]);
            if (!(o.tolerance > 0)) usage("--tolerance must be positive");
        } else if (a == "--font") {
            if (i + 1 >= argc) usage("missing value after --font");
            o.font = argv[++i];
        } else if (a == "--help" || a == "-h") {
            usage("lower bounds of accumulation designs on the compare_glyphs glyph set");
        } else {
            usage(("unknown argument " + a).c_str());
        }
    }
    return o;
}

// Where the fill's batch sink (raster::PolylineSink) hands its polylines: only a checksum is kept,
// so that the time is the flattening's alone.
struct ChecksumOut {
    unsigned checksum = 0;
    void push_polyline(const double* xy, std::size_t n) {
        checksum += static_cast<unsigned>(n) + static_cast<unsigned>(xy[2 * n - 1]);
    }
    void contour_end() {}
};

// One glyph, flattened once (the polygon casteljau's fill scan-converts at this tolerance).
struct Flat {
    int w = 0, h = 0;
    std::vector<Seg> segs;
    casteljau::Path polygon;  // the same edges as a path of lines
    FT_Outline outline{};     // for FreeType (owned by the GlyphSet)
};

// Best (smallest) nanoseconds per glyph over `runs` rounds of whole passes of at least min_time.
template <class F>
double time_ns(const Options& o, std::size_t glyphs, F&& pass) {
    int passes = 1;
    if (!o.quick) {
        for (;;) {
            const double t0 = bench::thread_cpu_seconds();
            for (int p = 0; p < passes; ++p) pass();
            if (bench::thread_cpu_seconds() - t0 >= o.min_time || passes > (1 << 20)) break;
            passes *= 2;
        }
    }
    double best = 1e300;
    for (int r = 0; r < o.runs; ++r) {
        const double t0 = bench::thread_cpu_seconds();
        for (int p = 0; p < passes; ++p) pass();
        best = std::min(best, (bench::thread_cpu_seconds() - t0) / passes);
    }
    return best * 1e9 / static_cast<double>(glyphs);
}

int run(const Options& o) {
    const bench::Font font(o.font);
    std::printf("accumulation_floor: %s, glyph set of compare_glyphs, unhinted, tolerance %g px\n", font.path().c_str(),
                o.tolerance);
    std::printf(
        "nanoseconds per glyph (thread CPU time, best of %d rounds); casteljau and the floors get the "
        "polygon already flattened\n\n",
        o.runs);
    std::printf(
        "| px | edges/glyph | FreeType (all) | budget = FreeType / 1.5 | flatten | casteljau (exact on) | "
        "casteljau (exact off) | dense float | row vector |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    int status = 0;
    for (const int px : o.sizes) {
        const bench::GlyphSet set(font, px);
        std::vector<Flat> flats(set.size());
        std::size_t edges = 0;
        int maxw = 1, maxh = 1;
        for (std::size_t i = 0; i < set.size(); ++i) {
            const bench::Glyph& g = set.glyphs()[i];
            Flat& f = flats[i];
            f.w = g.box.width;
            f.h = g.box.height;
            f.outline = g.outline;
            casteljau::Polyline pl;
            casteljau::flatten(g.path, g.to_box, o.tolerance, pl, casteljau::FlattenMode::AreaBalanced);
            std::size_t b = 0;
            for (const std::uint32_t e : pl.contour_ends) {
                if (e > b) {
                    f.polygon.move_to(pl.points[b]);
                    for (std::size_t k = b + 1; k < e; ++k) f.polygon.line_to(pl.points[k]);
                    f.polygon.close();
                }
                for (std::size_t k = b; k < e; ++k) {
                    const casteljau::Point p = pl.points[k], q = pl.points[k + 1 < e ? k + 1 : b];
                    if (p.x == q.x && p.y == q.y) continue;
                    f.segs.push_back({static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(q.x),
                                      static_cast<float>(q.y)});
                }
                b = e;
            }
            edges += f.segs.size();
            maxw = std::max(maxw, f.w);
            maxh = std::max(maxh, f.h);
        }
        // Scratch, zero between glyphs; row vectors use rows of whole SIMD vectors (out too).
        const int vstride = floorbench::row_vector_stride(maxw);
        std::vector<float> acc(static_cast<std::size_t>(std::max(vstride, maxw + 2)) * static_cast<std::size_t>(maxh),
                               0.0f);
        std::vector<std::uint8_t> out(static_cast<std::size_t>(vstride) * static_cast<std::size_t>(maxh), 0);
        std::vector<std::uint8_t> ref(static_cast<std::size_t>(maxw) * static_cast<std::size_t>(maxh), 0);
        unsigned checksum = 0;
        auto job = [&](const Flat& f, int stride) {
            return floorbench::Job{f.segs.data(), f.segs.size(), f.w, f.h, acc.data(), out.data(), stride};
        };

        // Agreement: both floors against casteljau (exact off) on the same polygons.
        casteljau::Rasterizer rast;
        casteljau::FillOptions off;
        off.exact_overlaps = false;
        int worst_dense = 0, worst_vector = 0;
        for (const Flat& f : flats) {
            std::memset(ref.data(), 0, ref.size());
            bench::BufferSink sink(ref.data(), f.w);
            rast.fill(f.polygon, casteljau::Affine{}, off, casteljau::IRect{0, 0, f.w, f.h}, sink);
            floorbench::dense_float(job(f, f.w + 2));
            for (int y = 0; y < f.h; ++y)
                for (int x = 0; x < f.w; ++x)
                    worst_dense = std::max(worst_dense, std::abs(out[static_cast<std::size_t>(y) * f.w + x] -
                                                                 ref[static_cast<std::size_t>(y) * f.w + x]));
            const int s = floorbench::row_vector_stride(f.w);
            floorbench::row_vector(job(f, s));
            for (int y = 0; y < f.h; ++y)
                for (int x = 0; x < f.w; ++x)
                    worst_vector = std::max(worst_vector, std::abs(out[static_cast<std::size_t>(y) * s + x] -
                                                                   ref[static_cast<std::size_t>(y) * f.w + x]));
        }
        if (worst_dense > 1 || worst_vector > 1) {
            std::fprintf(
                stderr,
                "FAIL: %d px: a floor disagrees with casteljau (exact off): dense float %d/255, row vector %d/255\n",
                px, worst_dense, worst_vector);
            status = 1;
        }

        const double ft = time_ns(o, flats.size(), [&] {
            for (const Flat& f : flats) {
                std::memset(ref.data(), 0, static_cast<std::size_t>(f.w) * static_cast<std::size_t>(f.h));
                bench::render_freetype(font.library(), f.outline, f.w, f.h, ref.data());
                checksum += ref[0];
            }
        });
        auto cast = [&](bool exact) {
            casteljau::FillOptions fo;
            fo.exact_overlaps = exact;
            return time_ns(o, flats.size(), [&] {
                for (const Flat& f : flats) {
                    std::memset(ref.data(), 0, static_cast<std::size_t>(f.w) * static_cast<std::size_t>(f.h));
                    bench::BufferSink sink(ref.data(), f.w);
                    rast.fill(f.polygon, casteljau::Affine{}, fo, casteljau::IRect{0, 0, f.w, f.h}, sink);
                    checksum += ref[0];
                }
            });
        };
        const double on = cast(true), offt = cast(false);
        ChecksumOut batches;
        const double flat = time_ns(o, flats.size(), [&] {
            for (const bench::Glyph& g : set.glyphs()) {
                casteljau::raster::PolylineSink<ChecksumOut> sink(batches);
                casteljau::flatten_into(g.path, g.to_box, o.tolerance, nullptr, sink, true);
                sink.end();
            }
        });
        checksum += batches.checksum;
        const double dense = time_ns(o, flats.size(), [&] {
            for (const Flat& f : flats) {
                floorbench::dense_float(job(f, f.w + 2));
                checksum += out[0];
            }
        });
        const double vec = time_ns(o, flats.size(), [&] {
            for (const Flat& f : flats) {
                floorbench::row_vector(job(f, floorbench::row_vector_stride(f.w)));
                checksum += out[0];
            }
        });
        std::printf("| %d | %.1f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f |\n", px,
                    static_cast<double>(edges) / static_cast<double>(flats.size()), ft, ft / 1.5, flat, on, offt, dense,
                    vec);
        std::fflush(stdout);
        if (checksum == 0xffffffffu) std::printf(" ");  // keep the work observable
    }
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "accumulation_floor: error: %s\n", e.what());
        return 1;
    }
}
#endif  // HWY_ONCE
