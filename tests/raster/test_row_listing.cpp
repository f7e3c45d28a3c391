// The row vectors' listing of a polyline's pieces (list_row_pieces, src/raster/row_listing.cpp),
// forward and reversed, against the edge-by-edge walk it replaces (list_edge_pieces), on every SIMD
// target this CPU runs.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "core/simd_dispatch.hpp"
#include "raster/engine.hpp"

using namespace casteljau;
using namespace casteljau::raster;

namespace {

// What the engine listed before the vector listing: each edge through list_edge_pieces, from the
// first point to the last or (reverse) from the last to the first.
std::vector<RowPiece> one_by_one(const std::vector<double>& xy, bool reverse, double fh, std::size_t& edges) {
    const std::size_t n = xy.size() / 2;
    std::vector<RowPiece> out(64 * n + 8);
    RowPiece* p = out.data();
    auto at = [&](std::size_t i) { return reverse ? n - 1 - i : i; };
    auto y_at = [&](std::size_t i) { return xy[2 * at(i) + 1] < fh ? xy[2 * at(i) + 1] : fh; };
    for (std::size_t i = 1; i < n; ++i) {
        const double x0 = xy[2 * at(i - 1)], y0 = y_at(i - 1), x1 = xy[2 * at(i)], y1 = y_at(i);
        if (x0 == x1 && y0 == y1) continue;
        ++edges;
        if (y0 != y1) p = list_edge_pieces(p, x0, y0, x1, y1);
    }
    out.resize(static_cast<std::size_t>(p - out.data()));
    return out;
}

// A polyline of n points in [0, w] x [0, h + 2] (y past h is held at h), mixing the cases the
// listing tells apart: edges inside one row, over two rows and over many, up and down, on row
// boundaries, horizontal, vertical, of length zero and of tiny height, and signed zeros.
std::vector<double> random_polyline(std::mt19937& rng, std::size_t n, double w, double h) {
    std::uniform_real_distribution<double> ux(0, w), uy(0, h + 2), small(-0.6, 0.6), tiny(-1e-9, 1e-9);
    std::uniform_int_distribution<int> kind(0, 9), row(0, static_cast<int>(h));
    std::vector<double> xy;
    double x = ux(rng), y = uy(rng);
    for (std::size_t i = 0; i < n; ++i) {
        xy.push_back(x);
        xy.push_back(y);
        switch (kind(rng)) {
            case 0: x = ux(rng), y = uy(rng); break;                    // anywhere: often many rows
            case 1: y = row(rng); break;                                // onto a row boundary
            case 2: x = ux(rng); break;                                 // horizontal
            case 3: y = std::clamp(y + small(rng), 0.0, h + 2); break;  // vertical, short
            case 4: break;                                              // length zero
            case 5:
                y = std::clamp(y + tiny(rng), 0.0, h + 2);
                x = std::clamp(x + small(rng), 0.0, w);
                break;
            case 6:
                x = (kind(rng) & 1) ? -0.0 : 0.0;
                y = std::clamp(y + small(rng), 0.0, h + 2);
                break;
            case 7: y = std::nextafter(static_cast<double>(row(rng)), (kind(rng) & 1) ? 1e9 : -1.0); break;
            default:  // a short step: one row or two
                x = std::clamp(x + small(rng), 0.0, w);
                y = std::clamp(y + small(rng), 0.0, h + 2);
        }
    }
    return xy;
}

}  // namespace

TEST_CASE("row listing: every target lists the pieces of the edge-by-edge walk, bit for bit", "[raster][simd]") {
    std::mt19937 rng(20261203);
    const auto targets = simd::available_targets();
    REQUIRE(!targets.empty());
    for (int trial = 0; trial < 4000; ++trial) {
        const std::size_t n = 1 + static_cast<std::size_t>((trial / 2) % 37);
        const double w = 1 + trial % 64, h = 1 + (trial * 7) % 40;
        const std::vector<double> xy = random_polyline(rng, n, w, h);
        const bool reverse = trial % 2 == 1;
        std::size_t want_edges = 0;
        const std::vector<RowPiece> want = one_by_one(xy, reverse, h, want_edges);
        // The engine's room: the sum of the edges' heights plus two pieces per point. Past it, a
        // guard that must stay untouched.
        double rows = 0;
        for (std::size_t i = 1; i < n; ++i) rows += std::abs(std::min(xy[2 * i + 1], h) - std::min(xy[2 * i - 1], h));
        const std::size_t room = static_cast<std::size_t>(rows) + 2 * n;
        REQUIRE(want.size() + 2 <= room);
        for (std::int64_t t : targets) {
            INFO("target " << simd::target_name(t) << ", trial " << trial << ", " << n << " points"
                           << (reverse ? ", reversed" : ""));
            simd::restrict_targets(t);
            std::vector<RowPiece> got(room + 16);
            std::memset(got.data(), 0xA5, got.size() * sizeof(RowPiece));
            std::size_t edges = 0;
            const RowPiece* end = list_row_pieces(xy.data(), n, reverse, h, got.data(), edges);
            REQUIRE(static_cast<std::size_t>(end - got.data()) == want.size());
            CHECK(edges == want_edges);
            CHECK(std::memcmp(got.data(), want.data(), want.size() * sizeof(RowPiece)) == 0);
            bool guard = true;
            for (std::size_t i = room * sizeof(RowPiece); i < got.size() * sizeof(RowPiece); ++i)
                guard = guard && reinterpret_cast<const unsigned char*>(got.data())[i] == 0xA5;
            CHECK(guard);
        }
    }
    simd::restrict_targets(0);
}
