// bench/compare_glyphs.cpp: side-by-side glyph rasterization, casteljau against its peers, in one
// process on the same outlines.
//
// Every glyph of the benchmark set (glyph_set.hpp: DejaVu Sans, U+0021..U+007E and
// U+00A1..U+017F, unhinted) is loaded with FreeType once per pixel size and converted, outside the
// timed region, into each library's own path type. The timed work is "produce the 8-bit coverage
// of the glyph's box in a preallocated buffer", for every glyph of the set:
//   casteljau              Rasterizer::fill with a SpanSink copying rows into a reused buffer
//                          (cleared first), default options: exact, no topology given (so the
//                          winding sweep for every glyph below 16 px of box per verb, and the
//                          verdict of classify_topology above: the raw-path figure)
//   casteljau (font path)  the same with each glyph's topology decided once (untimed, in prepare),
//                          as the glyph cache does per glyph (the verdict for similarity maps,
//                          classify_topology(path, tolerance)): what text rendering runs
//   casteljau (font path: any-map verdict)  the same with the verdict for every affine map
//                          (classify_topology(path)): fewer CFF glyphs proven
//   casteljau (exact cells) exact, topology given as Overlapping and the winding sweep off: every
//                          glyph through the per-cell overlap check (also the exact reference
//                          below, made independently of the sweep)
//   casteljau (exact off)  the same with exact_overlaps off
//   fill_mask, fill_mask (exact off)
//                          Rasterizer::fill_mask, which allocates and returns a fresh Mask
//   FreeType               FT_Outline_Render, FT_RASTER_FLAG_AA, into a gray8 FT_Bitmap (cleared first)
//   AGG, Cairo, stb_truetype, stb (from font)   see peer_*.cpp
// Timing: thread CPU time (timer.hpp: the machine is shared). Each renderer is calibrated to N
// passes over the whole set lasting at least --min-time seconds; then --runs rounds run every
// renderer once in turn (round-robin, so a noisy neighbour hits all of them alike) and the best
// round counts. glyphs/s = glyphs x N / best.
// Before timing, every renderer's output is compared pixel by pixel with FreeType's and with an
// exact reference (mean and max absolute difference in 1/255), so nobody benchmarks a broken
// render and everybody's accuracy is on record; the program exits 1 when
// casteljau disagrees with FreeType beyond kMaxMeanVsFreeType or fill and fill_mask differ.
//
// Usage: compare_glyphs [--quick] [--runs R] [--min-time S] [--sizes 12,24,...] [--only NAMES]
//                       [--passes N] [--tolerance PX] [--no-check] [--font FILE]
//   --font      another font (default DejaVu Sans; e.g. fonts/LinLibertine_R.otf, CFF outlines)
//   --quick     smoke test: one pass, one run (used by ctest)
//   --no-check  skip the agreement pass (and its tables): for profiling the timed part alone
//   --only      time only the renderers named (comma-separated, exact names as in the table header,
//               e.g. --only "casteljau,FreeType"); accuracy is still checked for all. With
//               --passes N this is the profiling entry point (fixed work, no calibration)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "casteljau/raster.hpp"
#include "glyph_set.hpp"
#include "timer.hpp"
#include "renderer.hpp"

namespace {

using bench::Coverage;
using bench::GlyphSet;
using bench::Renderer;

// casteljau and FreeType both compute exact areas of slightly different polygons: FreeType flattens
// conics until |P0 - 2 P1 + P2| <= 1/4 px per axis (a deviation of up to 1/16 px, always on the
// concave side), casteljau to its own tolerance; and they differ where contours overlap (FreeType
// accumulates, casteljau is exact there). Their mean difference on this set is 0.05 to 1.5/255
// depending on size and casteljau's tolerance (1.44/255 at 12 px with the default 0.015 px; the
// program prints the table). A broken render (offset, flipped, wrong fill rule) is far beyond this bound.
constexpr double kMaxMeanVsFreeType = 2.0;
// The exact reference for the error table: casteljau with a 0.001 px polygon (its exact-area
// coverage is within a small fraction of 1/255 of the curves').
constexpr double kReferenceTolerance = 0.001;

struct Options : bench::CommonOptions {
    bool check = true;
    int passes = 0;  // fixed passes per run (0: calibrate; --quick: 1)
    std::string only;
    double tolerance = casteljau::kDefaultTolerance;
    std::string font = CASTELJAU_BENCH_FONT;  // --font: another TrueType or CFF (.otf) font
};

[[noreturn]] void usage(const char* msg) {
    std::fprintf(stderr,
                 "compare_glyphs: %s\nusage: compare_glyphs [--quick] [--runs R] [--min-time S] [--sizes 12,24,...]\n"
                 "                      [--only NAMES] [--passes N] [--tolerance PX] [--no-check] [--font FILE]\n",
                 msg);
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    auto value = [&](int& i) -> std::string {
        if (i + 1 >= argc) usage((std::string("missing value after ") + argv[i]).c_str());
        return argv[++i];
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (o.parse_common(argc, argv, i, usage)) {
            if (o.quick) o.passes = 1;
        } else if (a == "--no-check") {
            o.check = false;
        } else if (a == "--passes") {
            o.passes = std::max(1, std::atoi(value(i).c_str()));
        } else if (a == "--only") {
            o.only = value(i);
        } else if (a == "--font") {
            o.font = value(i);
        } else if (a == "--tolerance") {
            o.tolerance = std::atof(value(i).c_str());
            if (!(o.tolerance > 0)) usage("--tolerance must be positive");
        } else if (a == "--help" || a == "-h") {
            usage("side-by-side glyph rasterization benchmark");
        } else {
            usage(("unknown argument " + a).c_str());
        }
    }
    return o;
}

// Whether `name` is one of the comma-separated names in `list`.
bool in_list(const std::string& list, const std::string& name) {
    std::size_t p = 0;
    while (p <= list.size()) {
        std::size_t q = list.find(',', p);
        if (q == std::string::npos) q = list.size();
        if (list.compare(p, q - p, name) == 0) return true;
        p = q + 1;
    }
    return false;
}

// --- casteljau ---------------------------------------------------------------------------------

// How casteljau decides exactness in a run: default options (no topology given), from a verdict
// decided once per glyph (what the glyph cache does: the font path; or the verdict for every
// affine map, which the glyph cache used before), or always the exact cells.
enum class Verdict { PerFill, Cached, CachedAnyMap, ExactCells };

class CasteljauFill final : public Renderer {
public:
    CasteljauFill(bool exact, double tol, Verdict verdict = Verdict::PerFill) : exact_(exact), verdict_(verdict) {
        opts_.exact_overlaps = exact;
        opts_.tolerance = tol;
        if (verdict == Verdict::ExactCells) {
            opts_.topology = casteljau::Topology::Overlapping;
            opts_.winding_sweep = false;
        }
    }
    std::string name() const override {
        if (!exact_) return "casteljau (exact off)";
        switch (verdict_) {
            case Verdict::Cached: return "casteljau (font path)";
            case Verdict::CachedAnyMap: return "casteljau (font path: any-map verdict)";
            case Verdict::ExactCells: return "casteljau (exact cells)";
            default: return "casteljau";
        }
    }
    void prepare(const GlyphSet& set) override {
        set_ = &set;
        buf_.assign(set.max_box_pixels(), 0);
        verdicts_.clear();
        simple_ = 0;
        if (verdict_ == Verdict::Cached || verdict_ == Verdict::CachedAnyMap)
            for (const bench::Glyph& g : set.glyphs()) {
                // The glyph cache's verdict: for similarity maps (a glyph's map to pixels), proven
                // for this size and down to half of it.
                verdicts_.push_back(
                    verdict_ == Verdict::CachedAnyMap
                        ? casteljau::classify_topology(g.path)
                        : casteljau::classify_topology(g.path, 2 * opts_.tolerance / std::abs(g.to_box.a)));
                simple_ += verdicts_.back() == casteljau::Topology::Simple;
            }
    }
    Coverage render(std::size_t i) override {
        const bench::Glyph& g = set_->glyphs()[i];
        std::memset(buf_.data(), 0, g.box.pixels());
        sink_.buf = buf_.data();
        sink_.stride = g.box.width;
        sink_.height = g.box.height;
        if (verdict_ == Verdict::Cached || verdict_ == Verdict::CachedAnyMap) opts_.topology = verdicts_[i];
        rast_.fill(g.path, g.to_box, opts_, casteljau::IRect{0, 0, g.box.width, g.box.height}, sink_);
        return {buf_.data(), g.box.width, g.box};
    }
    const casteljau::RasterStats& stats() const { return rast_.last_stats(); }
    std::size_t simple_glyphs() const { return simple_; }

private:
    bool exact_;
    Verdict verdict_;
    std::vector<casteljau::Topology> verdicts_;
    std::size_t simple_ = 0;
    casteljau::FillOptions opts_;
    const GlyphSet* set_ = nullptr;
    casteljau::Rasterizer rast_;
    bench::BufferSink sink_;
    std::vector<std::uint8_t> buf_;
};

class CasteljauMask final : public Renderer {
public:
    CasteljauMask(bool exact, double tol) : exact_(exact) {
        opts_.exact_overlaps = exact;
        opts_.tolerance = tol;
    }
    std::string name() const override { return exact_ ? "fill_mask" : "fill_mask (exact off)"; }
    void prepare(const GlyphSet& set) override { set_ = &set; }
    Coverage render(std::size_t i) override {
        const bench::Glyph& g = set_->glyphs()[i];
        mask_ = rast_.fill_mask(g.path, g.to_box, opts_);
        // The mask covers the control box in the box's pixel space: (0, 0) is the box's corner.
        bench::Box b{g.box.x0 + mask_.bounds.x0, g.box.y0 + mask_.bounds.y0, mask_.bounds.width(),
                     mask_.bounds.height()};
        return {mask_.data.data(), mask_.bounds.width(), b};
    }

private:
    bool exact_;
    casteljau::FillOptions opts_;
    const GlyphSet* set_ = nullptr;
    casteljau::Rasterizer rast_;
    casteljau::Mask mask_;
};

// --- FreeType ----------------------------------------------------------------------------------

class FreeTypeRenderer final : public Renderer {
public:
    std::string name() const override { return "FreeType"; }
    std::string version() const override {
        return std::to_string(FREETYPE_MAJOR) + "." + std::to_string(FREETYPE_MINOR) + "." +
               std::to_string(FREETYPE_PATCH);
    }
    void prepare(const GlyphSet& set) override {
        set_ = &set;
        buf_.assign(set.max_box_pixels(), 0);
    }
    Coverage render(std::size_t i) override {
        const bench::Glyph& g = set_->glyphs()[i];
        std::memset(buf_.data(), 0, g.box.pixels());
        bench::render_freetype(set_->font().library(), g.outline, g.box.width, g.box.height, buf_.data());
        return {buf_.data(), g.box.width, g.box};
    }

private:
    const GlyphSet* set_ = nullptr;
    std::vector<std::uint8_t> buf_;
};

// --- harness -----------------------------------------------------------------------------------

double time_passes(Renderer& r, std::size_t n, int passes, unsigned& checksum) {
    const double t0 = bench::thread_cpu_seconds();
    for (int p = 0; p < passes; ++p) {
        for (std::size_t i = 0; i < n; ++i) {
            const Coverage c = r.render(i);
            checksum += c.data ? c.data[0] : 0u;
        }
    }
    return bench::thread_cpu_seconds() - t0;
}

struct Owned {  // a copy of one render, for comparisons
    std::vector<std::uint8_t> data;
    Coverage cov;
};

Owned copy_of(const Coverage& c) {
    Owned o;
    o.data.resize(static_cast<std::size_t>(c.stride) * static_cast<std::size_t>(c.box.height));
    if (!o.data.empty()) std::memcpy(o.data.data(), c.data, o.data.size());
    o.cov = {o.data.data(), c.stride, c.box};
    return o;
}

struct Result {
    double glyphs_per_s = 0;
    int passes = 0;
    bench::DiffStats vs_freetype, vs_casteljau, vs_reference;
};

std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    const Options opt = parse(argc, argv);
    try {
        bench::Font font(opt.font);
        std::vector<std::unique_ptr<Renderer>> rs;
        rs.push_back(std::make_unique<CasteljauFill>(true, opt.tolerance));
        rs.push_back(std::make_unique<CasteljauFill>(false, opt.tolerance));
        rs.push_back(std::make_unique<CasteljauMask>(true, opt.tolerance));
        rs.push_back(std::make_unique<CasteljauMask>(false, opt.tolerance));
        rs.push_back(std::make_unique<FreeTypeRenderer>());
        rs.push_back(std::make_unique<CasteljauFill>(true, opt.tolerance, Verdict::Cached));
        rs.push_back(std::make_unique<CasteljauFill>(true, opt.tolerance, Verdict::ExactCells));
        rs.push_back(std::make_unique<CasteljauFill>(true, opt.tolerance, Verdict::CachedAnyMap));
#ifdef CASTELJAU_HAVE_AGG
        rs.push_back(bench::make_agg_renderer());
#endif
#ifdef CASTELJAU_HAVE_CAIRO
        rs.push_back(bench::make_cairo_renderer());
#endif
#ifdef CASTELJAU_HAVE_STB
        rs.push_back(bench::make_stb_renderer(false));
        rs.push_back(bench::make_stb_renderer(true));
#endif
        const std::size_t kCast = 0, kCastOff = 1, kMask = 2, kMaskOff = 3, kFT = 4, kFont = 5;
        std::vector<bool> timed(rs.size(), true);
        if (!opt.only.empty())
            for (std::size_t r = 0; r < rs.size(); ++r) timed[r] = in_list(opt.only, rs[r]->name());

        std::printf("compare_glyphs: %s, %zu codepoints (U+0021..U+007E, U+00A1..U+017F), unhinted\n",
                    font.path().c_str(), bench::benchmark_codepoints().size());
        std::printf("renderers:");
        for (const auto& r : rs) {
            const std::string v = r->version();
            std::printf(" %s%s%s%s;", r->name().c_str(), v.empty() ? "" : " (", v.c_str(), v.empty() ? "" : ")");
        }
        std::printf("\ncasteljau tolerance %.3g px; ", opt.tolerance);
        if (opt.passes > 0)
            std::printf("timing (thread CPU time): best of %d run(s) of %d pass(es) over the set\n\n", opt.runs,
                        opt.passes);
        else
            std::printf("timing (thread CPU time): best of %d runs, each >= %.2f s of whole passes over the set\n\n",
                        opt.runs, opt.min_time);

        bool ok = true;
        unsigned checksum = 0;
        std::vector<std::vector<Result>> results(opt.sizes.size(), std::vector<Result>(rs.size()));
        struct SizeInfo {
            std::size_t glyphs, pixels, segments, exact_cells, curves;
        };
        std::vector<SizeInfo> info(opt.sizes.size());

        for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
            const GlyphSet set(font, opt.sizes[si]);
            const std::size_t n = set.size();
            for (auto& r : rs) r->prepare(set);

            // Agreement: every renderer against FreeType, against casteljau and against the exact
            // reference (casteljau at kReferenceTolerance, exact overlaps on), glyph by glyph.
            CasteljauFill reference(true, kReferenceTolerance, Verdict::ExactCells);
            reference.prepare(set);
            SizeInfo& in = info[si];
            in = {n, set.total_box_pixels(), 0, 0, 0};
            auto* cast = static_cast<CasteljauFill*>(rs[kCast].get());
            bench::DiffStats mask_off_vs_fill_off;
            for (std::size_t i = 0; i < (opt.check ? n : 0); ++i) {
                const Owned ft = copy_of(rs[kFT]->render(i));
                const Owned cj = copy_of(cast->render(i));
                const Owned ref = copy_of(reference.render(i));
                in.segments += cast->stats().segments;
                in.exact_cells += cast->stats().exact_cells;
                in.curves += set.glyphs()[i].curves;
                const Owned cj_off = copy_of(rs[kCastOff]->render(i));
                mask_off_vs_fill_off.add(rs[kMaskOff]->render(i), cj_off.cov);
                for (std::size_t r = 0; r < rs.size(); ++r) {
                    const Coverage c = rs[r]->render(i);
                    results[si][r].vs_freetype.add(c, ft.cov);
                    results[si][r].vs_casteljau.add(c, cj.cov);
                    results[si][r].vs_reference.add(c, ref.cov);
                }
            }
            if (opt.check) {
                // FreeType flattens cubics coarsely: on a CFF font its own mean error against the
                // reference passes 2/255 (2.4/255 at 24 px for Linux Libertine), so the bound is
                // that error plus 1/255 when it is larger.
                const double m = results[si][kCast].vs_freetype.mean();
                const double bound = std::max(kMaxMeanVsFreeType, results[si][kFT].vs_reference.mean() + 1.0);
                if (!(m <= bound)) {
                    std::fprintf(stderr, "FAIL: %d px: casteljau vs FreeType mean |diff| %.3f/255 > %.1f/255\n",
                                 opt.sizes[si], m, bound);
                    ok = false;
                }
                // The font path (a verdict decided once per glyph) must render like the default.
                if (results[si][kFont].vs_casteljau.max > 1) {
                    std::fprintf(stderr, "FAIL: %d px: the font path differs from casteljau's default (max %d/255)\n",
                                 opt.sizes[si], results[si][kFont].vs_casteljau.max);
                    ok = false;
                }
                if (results[si][kMask].vs_casteljau.max != 0) {
                    std::fprintf(stderr, "FAIL: %d px: fill_mask differs from fill (max %d/255)\n", opt.sizes[si],
                                 results[si][kMask].vs_casteljau.max);
                    ok = false;
                }
                if (mask_off_vs_fill_off.max != 0) {
                    std::fprintf(stderr,
                                 "FAIL: %d px: fill_mask (exact off) differs from fill (exact off) (max %d/255)\n",
                                 opt.sizes[si], mask_off_vs_fill_off.max);
                    ok = false;
                }
            }

            // Timing.
            for (std::size_t r = 0; r < rs.size(); ++r) {
                if (!timed[r]) continue;
                if (opt.passes > 0) {
                    results[si][r].passes = opt.passes;
                } else {
                    const double t1 = time_passes(*rs[r], n, 1, checksum);  // also warms up
                    results[si][r].passes = std::max(1, static_cast<int>(std::ceil(opt.min_time / std::max(t1, 1e-9))));
                }
            }
            std::vector<double> best(rs.size(), INFINITY);
            for (int run = 0; run < opt.runs; ++run) {
                for (std::size_t r = 0; r < rs.size(); ++r) {
                    if (!timed[r]) continue;
                    best[r] = std::min(best[r], time_passes(*rs[r], n, results[si][r].passes, checksum));
                }
            }
            for (std::size_t r = 0; r < rs.size(); ++r)
                if (timed[r]) results[si][r].glyphs_per_s = static_cast<double>(n) * results[si][r].passes / best[r];
            std::fprintf(stderr, "  %d px done (%zu of %zu glyphs proven simple by classify_topology)\n", opt.sizes[si],
                         static_cast<CasteljauFill*>(rs[kFont].get())->simple_glyphs(), n);
        }

        // --- tables (Markdown) ---
        if (opt.check) {
            std::printf("Glyph set per size (casteljau at tolerance %.3g px, exact overlaps on):\n\n", opt.tolerance);
            std::printf(
                "| px | glyphs | box pixels/glyph | curves/glyph | edges/glyph | exact cells/glyph | pixels changed by "
                "exact/glyph | by > 1/255 |\n");
            std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
            for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
                const SizeInfo& in = info[si];
                const double g = static_cast<double>(in.glyphs);
                const auto& d = results[si][kCastOff].vs_casteljau;
                std::printf("| %d | %zu | %.0f | %.1f | %.1f | %.2f | %.3f | %.3f |\n", opt.sizes[si], in.glyphs,
                            in.pixels / g, in.curves / g, in.segments / g, in.exact_cells / g,
                            static_cast<double>(d.changed) / g, static_cast<double>(d.over1) / g);
            }
        }
        std::printf("\nThroughput, thousands of glyphs per second (higher is better):\n\n| px |");
        for (std::size_t r = 0; r < rs.size(); ++r)
            if (timed[r]) std::printf(" %s |", rs[r]->name().c_str());
        std::printf("\n|---:|");
        for (std::size_t r = 0; r < rs.size(); ++r)
            if (timed[r]) std::printf("---:|");
        std::printf("\n");
        for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
            std::printf("| %d |", opt.sizes[si]);
            for (std::size_t r = 0; r < rs.size(); ++r)
                if (timed[r]) std::printf(" %s |", fmt("%.1f", results[si][r].glyphs_per_s / 1000).c_str());
            std::printf("\n");
        }

        if (timed[kCast]) {
            std::printf(
                "\nSpeed ratio: casteljau (fill, exact overlaps on) / peer; > 1 means casteljau is faster:\n\n| px |");
            for (std::size_t r = 0; r < rs.size(); ++r)
                if (r != kCast && timed[r]) std::printf(" vs %s |", rs[r]->name().c_str());
            std::printf("\n|---:|");
            for (std::size_t r = 0; r < rs.size(); ++r)
                if (r != kCast && timed[r]) std::printf("---:|");
            std::printf("\n");
            for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
                std::printf("| %d |", opt.sizes[si]);
                for (std::size_t r = 0; r < rs.size(); ++r)
                    if (r != kCast && timed[r])
                        std::printf(" %s |",
                                    fmt("%.2f", results[si][kCast].glyphs_per_s / results[si][r].glyphs_per_s).c_str());
                std::printf("\n");
            }
        }

        if (!opt.check) {
            std::printf("\n(agreement pass skipped: --no-check)\n(checksum %u)\n", checksum);
            return 0;
        }
        std::printf(
            "\nAgreement with FreeType: mean / max |difference| per pixel of the glyph boxes, in 1/255:\n\n| px |");
        for (std::size_t r = 0; r < rs.size(); ++r)
            if (r != kFT) std::printf(" %s |", rs[r]->name().c_str());
        std::printf("\n|---:|");
        for (std::size_t r = 0; r < rs.size(); ++r)
            if (r != kFT) std::printf("---:|");
        std::printf("\n");
        for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
            std::printf("| %d |", opt.sizes[si]);
            for (std::size_t r = 0; r < rs.size(); ++r) {
                if (r == kFT) continue;
                const auto& d = results[si][r].vs_freetype;
                std::printf(" %.3f / %d |", d.mean(), d.max);
            }
            std::printf("\n");
        }
        std::printf(
            "\nError against the exact reference (casteljau at %g px, exact overlaps on): mean / max |difference| "
            "in 1/255:\n\n| px |",
            kReferenceTolerance);
        for (std::size_t r = 0; r < rs.size(); ++r) std::printf(" %s |", rs[r]->name().c_str());
        std::printf("\n|---:|");
        for (std::size_t r = 0; r < rs.size(); ++r) std::printf("---:|");
        std::printf("\n");
        for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
            std::printf("| %d |", opt.sizes[si]);
            for (std::size_t r = 0; r < rs.size(); ++r) {
                const auto& d = results[si][r].vs_reference;
                std::printf(" %.3f / %d |", d.mean(), d.max);
            }
            std::printf("\n");
        }
        std::printf("\n(checksum %u)\n", checksum);
        if (!ok) {
            std::fprintf(stderr, "compare_glyphs: FAILED agreement checks\n");
            return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "compare_glyphs: error: %s\n", e.what());
        return 1;
    }
}
