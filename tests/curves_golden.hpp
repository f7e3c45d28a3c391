// A golden-image helper for the curve pictures (a copy of text_golden.hpp generalised to a
// folder; main has no shared tests/golden.hpp yet). golden/DIR/NAME.png is compared with the rendering
// under explicit tolerances (max and mean absolute difference per channel, 1/255 units). On a
// mismatch NAME.actual.png and NAME.diff.png are written to <build>/golden-out/DIR/. Setting the
// environment variable CASTELJAU_UPDATE_GOLDEN=1 rewrites the golden instead (an explicit opt-in;
// each golden test checks its picture independently before it gets here).
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <algorithm>
#include <cstdlib>
#include <string>

#include "casteljau/png.hpp"
#include "casteljau/paint.hpp"

namespace curves_test {

struct DiffStats {
    double mean = 0;  // mean absolute difference per channel, 1/255 units
    int max = 0;
    int max_x = 0, max_y = 0;
};

inline DiffStats compare_pixmaps(const casteljau::Pixmap& a, const casteljau::Pixmap& b) {
    DiffStats s;
    if (a.width() != b.width() || a.height() != b.height()) {
        s.max = 255;
        s.mean = 255;
        return s;
    }
    long sum = 0, n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 4; ++c) {
                const int d = std::abs(static_cast<int>(a.row(y)[4 * x + c]) - static_cast<int>(b.row(y)[4 * x + c]));
                sum += d;
                ++n;
                if (d > s.max) {
                    s.max = d;
                    s.max_x = x;
                    s.max_y = y;
                }
            }
    s.mean = n ? static_cast<double>(sum) / static_cast<double>(n) : 0;
    return s;
}

inline void check_golden(const std::string& dir, const std::string& name, const casteljau::Pixmap& actual, int max_tol, double mean_tol) {
    namespace fs = std::filesystem;
    const fs::path golden = fs::path(CASTELJAU_SOURCE_DIR) / "golden" / dir / (name + ".png");
    const char* update = std::getenv("CASTELJAU_UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        fs::create_directories(golden.parent_path());
        casteljau::write_png(actual, golden.string());
        WARN("golden " << golden.string() << " rewritten");
        return;
    }
    INFO("golden " << golden.string());
    REQUIRE(fs::exists(golden));  // create it with CASTELJAU_UPDATE_GOLDEN=1
    // Compare what a PNG round trip keeps (straight alpha): the golden's pixels vs ours encoded.
    const casteljau::Pixmap expected = casteljau::read_png(golden.string());
    const casteljau::Pixmap ours = casteljau::decode_png(casteljau::encode_png(actual));
    const DiffStats d = compare_pixmaps(ours, expected);
    INFO("size " << ours.width() << "x" << ours.height() << " vs golden " << expected.width() << "x" << expected.height()
                 << "; max " << d.max << "/255 at (" << d.max_x << ", " << d.max_y << "), mean " << d.mean << "/255");
    const bool ok = d.max <= max_tol && d.mean <= mean_tol;
    if (!ok) {
        const fs::path out = fs::path(CASTELJAU_BINARY_DIR) / "golden-out" / dir;
        fs::create_directories(out);
        casteljau::write_png(actual, (out / (name + ".actual.png")).string());
        if (expected.width() == ours.width() && expected.height() == ours.height()) {
            casteljau::Pixmap diff(ours.width(), ours.height());
            for (int y = 0; y < ours.height(); ++y)
                for (int x = 0; x < ours.width(); ++x) {
                    int m = 0;
                    for (int c = 0; c < 4; ++c)
                        m = std::max(m, std::abs(static_cast<int>(ours.row(y)[4 * x + c]) - static_cast<int>(expected.row(y)[4 * x + c])));
                    const std::uint8_t v = static_cast<std::uint8_t>(std::min(255, m * 8));
                    diff.set_pixel(x, y, {v, 0, 0, 255});
                }
            casteljau::write_png(diff, (out / (name + ".diff.png")).string());
        }
        UNSCOPED_INFO("wrote " << (out / (name + ".actual.png")).string());
    }
    CHECK(d.max <= max_tol);
    CHECK(d.mean <= mean_tol);
}

}  // namespace curves_test
