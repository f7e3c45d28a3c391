// Tests of the golden-image harness itself (tests/support/golden.*), in a scratch folder of the build tree.
#include <catch2/catch.hpp>

#include <filesystem>

#include "casteljau/png.hpp"
#include "golden.hpp"

using namespace casteljau;
using namespace casteljau::golden;
namespace fs = std::filesystem;

namespace {

Pixmap sample(int w, int h) {
    Pixmap p(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto v = static_cast<std::uint8_t>(10 * x + 40 * y);
            p.set_pixel(x, y, {v, v, v, 255});
        }
    return p;
}

}  // namespace

TEST_CASE("golden harness: difference and difference image", "[golden]") {
    const Pixmap a = sample(3, 2);
    Pixmap b = a;
    b.set_pixel(2, 1, {100, 90, 90, 255});  // was (60, 60, 60, 255): max channel difference 40
    b.set_pixel(0, 0, {0, 0, 3, 255});      // difference 3
    const Difference d = difference(a, b);
    CHECK_FALSE(d.size_mismatch);
    CHECK(d.max_abs == 40);
    CHECK(d.mean_abs == Approx(43.0 / 6));
    CHECK(d.worst_x == 2);
    CHECK(d.worst_y == 1);
    CHECK(d.expected == PremulPixel{60, 60, 60, 255});
    CHECK(d.actual == PremulPixel{100, 90, 90, 255});
    const Pixmap img = difference_image(a, b);
    CHECK(img.pixel(2, 1).r == 255);  // 8 x 40 clamped
    CHECK(img.pixel(0, 0).r == 24);   // 8 x 3
    CHECK(img.pixel(1, 0).r == 0);
    CHECK(img.pixel(1, 0).g == 255 / 4);  // the expected image shows through: max channel 255 (alpha) / 4
    CHECK(difference(a, sample(2, 3)).size_mismatch);
}

TEST_CASE("golden harness: missing, update, match, mismatch, size and refusal", "[golden]") {
    const std::string root = std::string(CASTELJAU_BINARY_DIR) + "/golden-selftest";
    fs::remove_all(root);
    Setup s{root + "/golden", root + "/out", false};
    const Pixmap img = sample(4, 3);
    const Validation ok{true, "checked"}, bad{false, "reference check failed"};
    const std::string name = "sub/dir/scene";

    // Missing golden: a failure, the actual image is written for inspection.
    Outcome o = compare_golden(s, name, img, {0, 0.0}, ok);
    CHECK_FALSE(o.ok);
    CHECK(o.wrote_outputs);
    CHECK(fs::exists(root + "/out/sub/dir/scene.actual.png"));
    CHECK_FALSE(fs::exists(root + "/golden/sub/dir/scene.png"));

    // Update mode without a passed independent check: refused, nothing written.
    s.update = true;
    o = compare_golden(s, name, img, {0, 0.0}, bad);
    CHECK_FALSE(o.ok);
    CHECK_FALSE(o.wrote_golden);
    CHECK(o.message.find("refusing") != std::string::npos);
    CHECK_FALSE(fs::exists(root + "/golden/sub/dir/scene.png"));

    // Update mode with it: written, round trip exact.
    o = compare_golden(s, name, img, {0, 0.0}, ok);
    CHECK(o.ok);
    CHECK(o.wrote_golden);
    REQUIRE(fs::exists(root + "/golden/sub/dir/scene.png"));
    CHECK(difference(read_png(root + "/golden/sub/dir/scene.png"), img).max_abs == 0);

    // Compare mode: identical matches with zero tolerance.
    s.update = false;
    fs::remove_all(root + "/out");
    o = compare_golden(s, name, img, {0, 0.0}, ok);
    CHECK(o.ok);
    CHECK_FALSE(o.wrote_outputs);

    // One pixel off by 3: fails at max 2, passes at max 3; the mean limit applies too.
    Pixmap off = img;
    off.set_pixel(1, 2, {static_cast<std::uint8_t>(img.pixel(1, 2).r + 3), img.pixel(1, 2).g, img.pixel(1, 2).b, 255});
    o = compare_golden(s, name, off, {2, 1.0}, ok);
    CHECK_FALSE(o.ok);
    CHECK(o.message.find("max 3/255") != std::string::npos);
    CHECK(o.message.find("(1, 2)") != std::string::npos);
    REQUIRE(fs::exists(root + "/out/sub/dir/scene.diff.png"));
    CHECK(read_png(root + "/out/sub/dir/scene.diff.png").pixel(1, 2).r == 24);
    CHECK(difference(read_png(root + "/out/sub/dir/scene.actual.png"), off).max_abs == 0);
    CHECK(compare_golden(s, name, off, {3, 1.0}, ok).ok);
    CHECK_FALSE(compare_golden(s, name, off, {3, 0.2}, ok).ok);  // mean 3 / 12 = 0.25

    // Size mismatch.
    o = compare_golden(s, name, sample(3, 3), {255, 255.0}, ok);
    CHECK_FALSE(o.ok);
    CHECK(o.message.find("4x3") != std::string::npos);

    // Update mode reports the previous difference.
    s.update = true;
    o = compare_golden(s, name, off, {0, 0.0}, ok);
    CHECK(o.ok);
    CHECK(o.message.find("previous golden: max 3/255") != std::string::npos);
    fs::remove_all(root);
}
