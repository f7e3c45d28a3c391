// SVG <image>: PNG from a data: URI and from a relative file, an .svgz document, and the refusals
// (missing and corrupt files, http URLs, absolute paths such as /etc/passwd, files outside the
// document's folder), each drawing nothing with a warning, never an error or a crash.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "cli_util.hpp"
#include "svg_test_util.hpp"

using namespace casteljau;
using namespace casteljau::test;
namespace fs = std::filesystem;

namespace {
std::string base64(const std::vector<std::uint8_t>& in) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const unsigned n =
            (in[i] << 16) | ((i + 1 < in.size() ? in[i + 1] : 0) << 8) | (i + 2 < in.size() ? in[i + 2] : 0);
        out += k[(n >> 18) & 63];
        out += k[(n >> 12) & 63];
        out += i + 1 < in.size() ? k[(n >> 6) & 63] : '=';
        out += i + 2 < in.size() ? k[n & 63] : '=';
    }
    return out;
}

std::vector<std::uint8_t> green_png() {
    Pixmap pm(2, 2);
    pm.fill(Color::rgba(0, 128, 0));
    return encode_png(pm);
}

void write(const fs::path& p, const std::string& s) {
    std::ofstream f(p, std::ios::binary);
    f << s;
}

const std::string kHead =
    "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' width='10' height='10'>";
const PremulPixel kGreen{0, 128, 0, 255};
}  // namespace

TEST_CASE("svg image: a PNG from a data: URI fills its viewport", "[svg][image]") {
    const SvgDocument doc = SvgDocument::parse(kHead + "<image width='10' height='10' href='data:image/png;base64," +
                                               base64(green_png()) + "'/></svg>");
    const Pixmap pm = doc.render();
    CHECK(pm.pixel(0, 0) == kGreen);
    CHECK(pm.pixel(9, 9) == kGreen);
}

TEST_CASE("svg image: relative files inside the folder load, everything else is refused", "[svg][image][bad-input]") {
    const fs::path d = scratch_dir("svg-image");
    fs::create_directories(d / "doc");
    const std::vector<std::uint8_t> png = green_png();
    write(d / "doc" / "ok.png", std::string(png.begin(), png.end()));
    write(d / "outside.png", std::string(png.begin(), png.end()));
    write(d / "doc" / "corrupt.png", std::string(png.begin(), png.begin() + 30));
    auto render = [&](const std::string& href, const std::string& root = {}) {
        write(d / "doc" / "a.svg", kHead + "<image width='10' height='10' xlink:href='" + href + "'/></svg>");
        const SvgDocument doc = SvgDocument::load((d / "doc" / "a.svg").string(), root);
        return std::make_pair(doc.render().pixel(5, 5), doc.warnings());
    };
    CHECK(render("ok.png").first == kGreen);
    for (const char* bad : {"missing.png", "corrupt.png", "http://example.com/a.png", "/etc/passwd",
                            "file:///etc/passwd", "../outside.png", "../../../../../../../etc/passwd"}) {
        INFO(bad);
        const auto [px, warnings] = render(bad);
        CHECK(px.a == 0);
        CHECK_FALSE(warnings.empty());
    }
    // A wider resource root lets ../ through, and only there.
    CHECK(render("../outside.png", d.string()).first == kGreen);
    // Parsed from memory there is no folder: files are refused.
    CHECK(SvgDocument::parse(kHead + "<image width='10' height='10' href='ok.png'/></svg>").render().pixel(5, 5).a ==
          0);
}

TEST_CASE("svg: an .svgz file (gzip) is read, a corrupt one is a clear error", "[svg][image]") {
    const std::string text = kHead + "<rect width='10' height='10' fill='green'/></svg>";
    const std::string gz = casteljau::test::gzip(text);
    const std::string_view bytes = gz;
    CHECK(SvgDocument::parse(bytes).render().pixel(5, 5) == kGreen);
    CHECK_THROWS_AS(SvgDocument::parse(bytes.substr(0, bytes.size() / 2)), Error);
}

TEST_CASE("svg image: SVG images nest 4 deep, a fifth level is skipped with a warning", "[svg][image][limits]") {
    REQUIRE(current_limits().svg_image_nesting == 4);
    const fs::path d = scratch_dir("svg-image-nesting");
    fs::create_directories(d);
    // level0.svg draws level1.svg as an image, and so on; the deepest level paints green.
    auto chain = [&](int levels) {
        for (int i = 0; i < levels; ++i)
            write(d / ("level" + std::to_string(i) + ".svg"),
                  kHead + "<image width='10' height='10' href='level" + std::to_string(i + 1) + ".svg'/></svg>");
        write(d / ("level" + std::to_string(levels) + ".svg"),
              kHead + "<rect width='10' height='10' fill='green'/></svg>");
        return SvgDocument::load((d / "level0.svg").string());
    };
    const SvgDocument four = chain(4);  // images at nesting 1..4
    CHECK(four.render().pixel(5, 5) == kGreen);
    const SvgDocument five = chain(5);
    CHECK(five.render().pixel(5, 5).a == 0);
    bool warned = false;
    for (const std::string& w : five.warnings()) warned = warned || w.find("nested deeper than 4") != std::string::npos;
    CHECK(warned);
}
