// Decodes every reference PNG of the resvg conformance corpus (../shared/conformance/resvg): real
// oxipng-optimised files (palette, grey and grey+alpha at 1, 2, 4 and 8 bits, RGBA). Checks each
// size against the corpus's size rule (its README.md, "How the reference PNGs were made") and
// each pixel against stb_image, an independent decoder.
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/png.hpp"
#include "png_test_util.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;

namespace {

// The value of attribute `name` in an XML start tag, or "" when absent.
std::string attribute(const std::string& tag, const std::string& name) {
    const std::string key = name + "=\"";
    for (std::size_t at = tag.find(key); at != std::string::npos; at = tag.find(key, at + 1)) {
        const char before = at == 0 ? ' ' : tag[at - 1];
        if (before != ' ' && before != '\t' && before != '\n' && before != '\r') continue;
        const std::size_t start = at + key.size();
        const std::size_t end = tag.find('"', start);
        if (end == std::string::npos) return {};
        return tag.substr(start, end - start);
    }
    return {};
}

// The intrinsic size W x H of an SVG as the corpus defines it: the root width/height, else the
// viewBox size. Returns false when the file has neither in plain numbers.
bool intrinsic_size(const fs::path& svg, double& w, double& h) {
    std::ifstream in(svg, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    // The root: the first "<svg" or "<prefix:svg" start tag (one test spells it <svg:svg ...>).
    std::size_t start = std::string::npos;
    for (std::size_t at = text.find("svg"); at != std::string::npos && start == std::string::npos;
         at = text.find("svg", at + 1)) {
        if (at + 3 >= text.size() || !(std::isspace(static_cast<unsigned char>(text[at + 3])) || text[at + 3] == '>'))
            continue;
        if (at > 0 && text[at - 1] == '<') start = at - 1;
        if (at > 0 && text[at - 1] == ':') {
            std::size_t b = at - 1;
            while (b > 0 && std::isalnum(static_cast<unsigned char>(text[b - 1]))) --b;
            if (b > 0 && text[b - 1] == '<') start = b - 1;
        }
    }
    if (start == std::string::npos) return false;
    const std::string tag = text.substr(start, text.find('>', start) - start);
    double vb[4] = {0, 0, 0, 0};
    const std::string viewbox = attribute(tag, "viewBox");
    std::istringstream vs(viewbox);
    const bool has_vb = static_cast<bool>(vs >> vb[0] >> vb[1] >> vb[2] >> vb[3]);
    auto number = [](const std::string& s, double& out) {
        if (s.empty()) return false;
        char* end = nullptr;
        out = std::strtod(s.c_str(), &end);
        return *end == '\0';
    };
    if (!number(attribute(tag, "width"), w)) {
        if (!has_vb) return false;
        w = vb[2];
    }
    if (!number(attribute(tag, "height"), h)) {
        if (!has_vb) return false;
        h = vb[3];
    }
    return true;
}

}  // namespace

TEST_CASE("decode_png: every resvg reference PNG decodes, with the size rule's dimensions and stb_image's pixels",
          "[png]") {
    const fs::path root = casteljau::test::shared_dir() / "conformance" / "resvg";
    std::ifstream manifest(root / "manifest.tsv");
    if (!manifest)
        CASTELJAU_SKIP((root / "manifest.tsv").string()
                       << " is absent (the shared corpus lives in ../shared next to the source tree; "
                          "set CASTELJAU_SHARED_DIR to point elsewhere)");
    std::string line;
    std::getline(manifest, line);  // header: svg_path png_path category needs_gradients note
    REQUIRE(line.rfind("svg_path\tpng_path\t", 0) == 0);

    int files = 0, frame_checked = 0;
    std::set<std::pair<int, int>> formats;  // (colour type, bit depth) seen in the files
    while (std::getline(manifest, line)) {
        if (line.empty()) continue;
        std::vector<std::string> f;
        std::istringstream ls(line);
        for (std::string cell; std::getline(ls, cell, '\t');) f.push_back(cell);
        f.resize(5);
        const std::string& svg = f[0];
        const std::string& png = f[1];
        const std::string& category = f[2];
        const std::string& note = f[4];
        INFO(png);
        ++files;

        const std::vector<std::uint8_t> bytes = casteljau::read_file((root / png).string());
        REQUIRE(bytes.size() > 26);
        formats.emplace(bytes[25], bytes[24]);  // IHDR colour type and bit depth
        casteljau::Pixmap pm;
        try {
            pm = casteljau::decode_png(bytes);
        } catch (const casteljau::Error& e) {
            FAIL_CHECK("decode failed: " << e.what());
            continue;
        }

        // The size rule: tests/ are drawn 300 px wide, height ceil(300 H / W) with W, H the
        // intrinsic size rounded (minimum 1); extra/ at scale 1; three legacy files are 500x500.
        int want_w = 0, want_h = 0;
        if (note.find("legacy 500x500") != std::string::npos) {
            want_w = want_h = 500;
        } else {
            double w = 0, h = 0;
            REQUIRE(intrinsic_size(root / svg, w, h));
            const double rw = std::max(1.0, std::round(w)), rh = std::max(1.0, std::round(h));
            if (category == "extra") {
                want_w = static_cast<int>(rw);
                want_h = static_cast<int>(rh);
            } else {
                want_w = 300;
                want_h = static_cast<int>(std::ceil(300.0 * rh / rw));
            }
        }
        CHECK(pm.width() == want_w);
        CHECK(pm.height() == want_h);

        // Pixel for pixel against stb_image (straight RGBA8, premultiplied here).
        int sw = 0, sh = 0;
        const auto ref = png_test::stb_decode_rgba8(bytes, sw, sh);
        REQUIRE(sw == pm.width());
        REQUIRE(sh == pm.height());
        int wrong = 0;
        for (int y = 0; y < sh; ++y)
            for (int x = 0; x < sw; ++x) {
                const std::uint8_t* s =
                    &ref[(static_cast<std::size_t>(y) * static_cast<std::size_t>(sw) + static_cast<std::size_t>(x)) *
                         4];
                if (pm.pixel(x, y) != casteljau::premultiply(casteljau::Color{s[0], s[1], s[2], s[3]})) ++wrong;
            }
        CHECK(wrong == 0);

        // "frame-only" references (tests/ at scale 1.5) show only the 1-unit black frame at
        // x = 1: pixel column 1 lies inside its stroke [0.75, 2.25] px, the centre is empty.
        if (note.find("frame-only") != std::string::npos && category != "extra" && want_w == 300) {
            CHECK(pm.pixel(1, want_h / 2) == (casteljau::PremulPixel{0, 0, 0, 255}));
            CHECK(pm.pixel(150, want_h / 2) == (casteljau::PremulPixel{0, 0, 0, 0}));
            ++frame_checked;
        }
    }
    CHECK(files == 495);
    CHECK(frame_checked >= 30);
    // The corpus exercises the decoder's conversions: palette at 1, 2, 4, 8 bits, 1-bit grey,
    // grey+alpha and RGBA.
    for (const auto& fmt : {std::pair{3, 1}, std::pair{3, 2}, std::pair{3, 4}, std::pair{3, 8}, std::pair{0, 1},
                            std::pair{4, 8}, std::pair{6, 8}}) {
        INFO("colour type " << fmt.first << ", bit depth " << fmt.second);
        CHECK(formats.count(fmt) == 1);
    }
}
