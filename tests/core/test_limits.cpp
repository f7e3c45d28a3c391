// Run-time limits (casteljau/limits.hpp): the defaults are the documented ones, set_limits refuses
// values outside [minimum, ceiling] without changing anything, and every field, lowered, is crossed
// through the library call it guards and gives the documented error or warning.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/flatten.hpp"
#include "casteljau/font_database.hpp"
#include "casteljau/font.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/image.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/png.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/stroke.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/svg_path.hpp"
#include "casteljau/text.hpp"
#include "svg_test_util.hpp"
#include "text_support.hpp"

using namespace casteljau;

namespace {

// Applies a change to the default limits for the scope of a test, and restores the defaults.
class ScopedLimits {
public:
    template <class F>
    explicit ScopedLimits(F&& change) {
        Limits l;
        change(l);
        set_limits(l);
    }
    ~ScopedLimits() { reset_limits(); }
    ScopedLimits(const ScopedLimits&) = delete;
    ScopedLimits& operator=(const ScopedLimits&) = delete;
};

// The kind and message of the Error `f` throws; fails the test when it throws none.
template <class F>
std::pair<ErrorKind, std::string> error_of(F&& f) {
    try {
        f();
    } catch (const Error& e) { return {e.kind(), e.what()}; }
    FAIL("no Error thrown");
    return {};
}

std::string svg(const std::string& body, int w = 40, int h = 40) { return test::svg_text(body, w, h); }

bool has_warning(const SvgDocument& doc, const std::string& needle) {
    for (const std::string& w : doc.warnings())
        if (w.find(needle) != std::string::npos) return true;
    return false;
}

std::string base64(const std::string& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8) |
                           static_cast<unsigned char>(in[i + 2]);
        out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
    }
    if (i + 1 == in.size()) {
        const unsigned v = static_cast<unsigned char>(in[i]) << 16;
        out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == in.size()) {
        const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8);
        out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
    }
    return out;
}

}  // namespace

TEST_CASE("limits: the defaults are the documented values, and reset restores them", "[limits]") {
    const Limits d = current_limits();
    CHECK(d.canvas_dimension == 32768);
    CHECK(d.canvas_pixels == (1LL << 28));
    CHECK(d.path_points == (std::size_t(1) << 24));
    CHECK(d.flattened_segments == (std::size_t(1) << 23));
    CHECK(d.nesting_depth == 64);
    CHECK(d.svg_elements == 1'000'000);
    CHECK(d.svg_image_nesting == 4);
    CHECK(d.svgz_bytes == (std::size_t(64) << 20));
    CHECK(d.css_rules == 10'000);
    CHECK(d.svg_text_chars == 100'000);
    CHECK(d.filter_pixels == (1LL << 24));
    CHECK(d.filter_primitives == 1000);
    CHECK(d.map_positions == (std::size_t(1) << 27));
    CHECK(d.dashes == (std::size_t(1) << 18));
    CHECK(d.font_file_bytes == (std::uint64_t(512) << 20));
    CHECK(d.png_chunk_bytes == (std::size_t(16) << 20));
    CHECK(d.png_ancillary_chunks == 1000);
    CHECK(d.jpeg_working_memory == (std::uint64_t(512) << 20));
    CHECK(d.canvas_save_depth == 1024);
    CHECK(d.text_bytes == (std::size_t(16) << 20));
    CHECK(d.input_bytes == (std::uint64_t(1) << 30));
    CHECK(d.exact_work == 50'000'000);
    {
        ScopedLimits s([](Limits& l) { l.css_rules = 7; });
        CHECK(current_limits().css_rules == 7);
    }
    CHECK(current_limits().css_rules == 10'000);
}

TEST_CASE("limits: values below the minimum or above the ceiling are refused and change nothing", "[limits]") {
    const Limits ceil = Limits::ceilings();
    CHECK(ceil.canvas_dimension == 32768);  // the raster engine's types are sized for these
    CHECK(ceil.canvas_pixels == (1LL << 28));
    CHECK(ceil.path_points == (std::size_t(1) << 24));
    CHECK(ceil.flattened_segments == (std::size_t(1) << 23));
    CHECK(ceil.nesting_depth == 256);

    Limits l;
    l.canvas_dimension = 40000;
    l.css_rules = 3;
    auto [kind, msg] = error_of([&] { set_limits(l); });
    CHECK(kind == ErrorKind::InvalidArgument);
    CHECK_THAT(msg, Catch::Contains("canvas_dimension") && Catch::Contains("32768"));
    CHECK(current_limits().css_rules == 10'000);

    l = Limits{};
    l.nesting_depth = 0;
    CHECK(error_of([&] { set_limits(l); }).second.find("nesting_depth must be 1 to 256") != std::string::npos);
    l = Limits{};
    l.svg_image_nesting = -1;
    CHECK(error_of([&] { set_limits(l); }).first == ErrorKind::InvalidArgument);
    l.svg_image_nesting = 0;  // allowed: no SVG inside SVG
    CHECK_NOTHROW(set_limits(l));
    CHECK_NOTHROW(set_limits(Limits::ceilings()));
    CHECK(current_limits().svg_elements == 100'000'000);
    reset_limits();
    CHECK(current_limits().svg_elements == 1'000'000);
}

TEST_CASE("limits: canvas_dimension and canvas_pixels bound pixmaps, decoded PNGs and tiles", "[limits]") {
    const auto png = encode_png(Pixmap(101, 2));
    ScopedLimits s([](Limits& l) {
        l.canvas_dimension = 100;
        l.canvas_pixels = 150;
    });
    CHECK_NOTHROW(Pixmap(100, 1));
    auto [kind, msg] = error_of([] { Pixmap(101, 1); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("100 pixels"));
    std::tie(kind, msg) = error_of([] { Pixmap(100, 2); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("150 pixels"));
    std::tie(kind, msg) = error_of([&] { decode_png(png); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("101x2"));
    CHECK(error_of([] { SvgDocument::parse(svg("", 120, 1)).render(); }).first == ErrorKind::Limit);
}

TEST_CASE("limits: path_points bounds parsed path data, points lists and stroke outlines", "[limits]") {
    ScopedLimits s([](Limits& l) { l.path_points = 10; });
    CHECK_NOTHROW(parse_svg_path("M0 0 1 1 2 2 3 3 4 4 5 5 6 6 7 7 8 8 9 9"));
    auto [kind, msg] = error_of([] { parse_svg_path("M0 0 1 1 2 2 3 3 4 4 5 5 6 6 7 7 8 8 9 9 10 10"); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("10 points"));
    CHECK(error_of([] { parse_points("0 0 1 1 2 2 3 3 4 4 5 5 6 6 7 7 8 8 9 9 10 10", false); }).first ==
          ErrorKind::Limit);
    Path p;
    p.move_to({0, 0});
    for (int i = 1; i < 8; ++i) p.line_to({i * 10.0, (i % 2) * 10.0});
    StrokeStyle st;
    st.width = 2;
    CHECK(error_of([&] { stroke(p, st); }).first == ErrorKind::Limit);
}

TEST_CASE("limits: flattened_segments bounds flattening and filling", "[limits]") {
    Path circle;
    circle.add_ellipse({50, 50}, 40, 40);
    ScopedLimits s([](Limits& l) { l.flattened_segments = 8; });
    Polyline out;
    auto [kind, msg] = error_of([&] { flatten(circle, Affine{}, 0.015, out); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("more than 8"));
    Rasterizer r;
    CHECK(error_of([&] { r.fill_mask(circle, Affine{}); }).first == ErrorKind::Limit);
    FillOptions swept;  // not proven simple: the winding sweep takes the edges
    swept.topology = Topology::Overlapping;
    CHECK(error_of([&] { r.fill_mask(circle, Affine{}, swept); }).first == ErrorKind::Limit);
    FillOptions cells = swept;
    cells.winding_sweep = false;
    CHECK(error_of([&] { r.fill_mask(circle, Affine{}, cells); }).first == ErrorKind::Limit);
    Path square;
    square.add_rect(Rect::from_xywh(1, 1, 5, 5));
    CHECK_NOTHROW(r.fill_mask(square, Affine{}));
}

TEST_CASE("limits: nesting_depth bounds SVG elements, GeoJSON collections and canvas layers", "[limits]") {
    std::string deep, closing;
    for (int i = 0; i < 6; ++i) {
        deep += "<g>";
        closing += "</g>";
    }
    const std::string doc = svg(deep + "<rect width='10' height='10'/>" + closing);
    CHECK_NOTHROW(SvgDocument::parse(doc).render());
    const std::string collection =
        R"({"type":"GeometryCollection","geometries":[{"type":"GeometryCollection","geometries":[{"type":"GeometryCollection","geometries":[]}]}]})";
    CHECK_NOTHROW(read_geojson(collection));
    {
        ScopedLimits s([](Limits& l) { l.nesting_depth = 4; });
        auto [kind, msg] = error_of([&] { SvgDocument::parse(doc).render(); });
        CHECK(kind == ErrorKind::Limit);
        CHECK_THAT(msg, Catch::Contains("nested deeper than 4"));
        {
            ScopedLimits s2([](Limits& l) { l.nesting_depth = 2; });
            CHECK(error_of([&] { read_geojson(collection); }).first == ErrorKind::Limit);
            Pixmap pm(4, 4);
            Canvas c(pm);
            c.begin_layer(1);
            c.begin_layer(1);
            CHECK(error_of([&] { c.begin_layer(1); }).first == ErrorKind::Limit);
        }
    }
    // Raised to its ceiling, a document 250 elements deep renders (the readers recurse: this is
    // what the ceiling's stack budget is for).
    ScopedLimits s([](Limits& l) { l.nesting_depth = 256; });
    std::string very, very_closing;
    for (int i = 0; i < 250; ++i) {
        very += "<g>";
        very_closing += "</g>";
    }
    const Pixmap pm =
        SvgDocument::parse(svg(very + "<rect width='10' height='10' fill='#00f'/>" + very_closing)).render();
    CHECK(pm.pixel(5, 5).b == 255);
}

TEST_CASE("limits: svg_elements refuses a document that draws more elements (a use bomb)", "[limits]") {
    std::string rects;
    for (int i = 0; i < 6; ++i) rects += "<rect x='" + std::to_string(i) + "' width='1' height='1'/>";
    ScopedLimits s([](Limits& l) { l.svg_elements = 5; });
    auto [kind, msg] = error_of([&] { SvgDocument::parse(svg(rects)).render(); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("more than 5 elements"));
    // Two rects, each used twice: 2 + 4 + the uses themselves stay above 5 too.
    const std::string uses =
        "<defs><rect id='r' width='1' height='1'/></defs><use href='#r'/><use href='#r'/><use href='#r'/>";
    CHECK(error_of([&] { SvgDocument::parse(svg(uses)).render(); }).first == ErrorKind::Limit);
}

TEST_CASE("limits: svg_image_nesting 0 skips SVG images inside SVG documents with a warning", "[limits]") {
    const std::string inner = svg("<rect width='40' height='40' fill='#0f0'/>");
    const std::string outer =
        svg("<image width='40' height='40' href='data:image/svg+xml;base64," + base64(inner) + "'/>");
    CHECK(SvgDocument::parse(outer).render().pixel(20, 20).g == 255);
    ScopedLimits s([](Limits& l) { l.svg_image_nesting = 0; });
    const SvgDocument doc = SvgDocument::parse(outer);
    CHECK(doc.render().pixel(20, 20).a == 0);
    CHECK(has_warning(doc, "nested deeper than 0"));
}

TEST_CASE("limits: svgz_bytes bounds the inflated size of an .svgz", "[limits]") {
    const std::string text = svg("<rect width='10' height='10' fill='green'/>" + std::string(3000, ' '));
    const std::string gz = test::gzip(text);
    CHECK_NOTHROW(SvgDocument::parse(gz));
    ScopedLimits s([](Limits& l) { l.svgz_bytes = 1000; });
    auto [kind, msg] = error_of([&] { SvgDocument::parse(gz); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("more than 1000 bytes"));
}

TEST_CASE("limits: css_rules ignores the rules past it, with a warning", "[limits]") {
    const std::string doc = svg(
        "<style>rect{fill:#f00} .a{fill:#0f0} #b{fill:#00f}</style><rect id='b' class='a' width='10' height='10'/>");
    CHECK(SvgDocument::parse(doc).render().pixel(5, 5).b == 255);
    ScopedLimits s([](Limits& l) { l.css_rules = 2; });
    const SvgDocument d = SvgDocument::parse(doc);
    CHECK(has_warning(d, "more than 2 rules"));
    CHECK(d.render().pixel(5, 5).g == 255);  // the third rule (#b) was ignored
}

TEST_CASE("limits: svg_text_chars cuts SVG text with a warning", "[limits]") {
    const std::string doc =
        svg("<text x='0' y='20' font-family='DejaVu Sans' font-size='10'>abcdefghijklmnopqrst</text>", 200, 40);
    SvgOptions o;
    FontDatabaseOptions fo;
    fo.font_dirs = {CASTELJAU_TEST_FONT_DIR};
    fo.system_fonts = false;
    o.font_database = std::make_shared<const FontDatabase>(fo);
    o.font_family = "DejaVu Sans";
    CHECK_FALSE(has_warning(SvgDocument::parse(doc, o), "characters"));
    ScopedLimits s([](Limits& l) { l.svg_text_chars = 10; });
    CHECK(has_warning(SvgDocument::parse(doc, o), "more than 10 characters"));
}

TEST_CASE("limits: filter_pixels and filter_primitives bound SVG filters", "[limits]") {
    const std::string blur =
        "<filter id='f'><feGaussianBlur stdDeviation='2'/><feOffset dx='1'/></filter>"
        "<rect x='5' y='5' width='30' height='30' filter='url(#f)'/>";
    CHECK_NOTHROW(SvgDocument::parse(svg(blur)).render());
    {
        ScopedLimits s([](Limits& l) { l.filter_pixels = 100; });
        auto [kind, msg] = error_of([&] { SvgDocument::parse(svg(blur)).render(); });
        CHECK(kind == ErrorKind::Limit);
        CHECK_THAT(msg, Catch::Contains("limit of 100 pixels"));
    }
    ScopedLimits s([](Limits& l) { l.filter_primitives = 1; });
    auto [kind, msg] = error_of([&] { SvgDocument::parse(svg(blur)).render(); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("more than 1 primitives"));
}

TEST_CASE("limits: map_positions bounds the positions read from GeoJSON and TopoJSON", "[limits]") {
    const std::string square =
        R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1],[0,0]]]}})";
    const std::string two = R"({"type":"FeatureCollection","features":[)" + square + "," + square + "]}";
    CHECK(read_geojson(two).features.size() == 2);
    ScopedLimits s([](Limits& l) { l.map_positions = 9; });
    auto [kind, msg] = error_of([&] { read_geojson(two); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("more than 9 positions"));
    CHECK_THAT(msg, Catch::Contains("features[1]"));
    CHECK(read_geojson(square).features.size() == 1);
}

TEST_CASE("limits: dashes bounds the dashes made from one path", "[limits]") {
    Path line;
    line.move_to({0, 0});
    line.line_to({100, 0});
    const double pattern[] = {1, 1};
    CHECK_FALSE(dash(line, pattern, 0).empty());
    ScopedLimits s([](Limits& l) { l.dashes = 10; });
    auto [kind, msg] = error_of([&] { dash(line, pattern, 0); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("more than 10 dashes"));
    const double coarse[] = {20, 20};
    CHECK_NOTHROW(dash(line, coarse, 0));
}

TEST_CASE("limits: font_file_bytes bounds font files read from disk and memory", "[limits]") {
    CHECK_NOTHROW(Font::load(text_test::kDejaVu));
    ScopedLimits s([](Limits& l) { l.font_file_bytes = 1000; });
    auto [kind, msg] = error_of([] { Font::load(text_test::kDejaVu); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("larger than 1000 bytes"));
    CHECK(error_of([] { Font::from_memory(std::vector<std::uint8_t>(1001, 0)); }).first == ErrorKind::Limit);
}

TEST_CASE("limits: input_bytes bounds files, devices and map files read whole", "[limits]") {
    const std::string world = std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json";
    const std::string picture = std::string(CASTELJAU_SOURCE_DIR) + "/golden/install_scene.png";
    const std::size_t size = read_file(picture).size();
    {
        // Exactly at the limit still reads.
        ScopedLimits s([&](Limits& l) { l.input_bytes = size; });
        CHECK(read_file(picture).size() == size);
    }
    ScopedLimits s([&](Limits& l) { l.input_bytes = size - 1; });
    auto [kind, msg] = error_of([&] { read_file(picture); });
    CHECK(kind == ErrorKind::Limit);
    CHECK(msg == "'" + picture + "' is larger than " + std::to_string(size - 1) + " bytes (Limits::input_bytes)");
    // A device has no size to check first: its bytes are counted as they arrive.
    CHECK(error_of([] { read_file("/dev/zero"); }).first == ErrorKind::Limit);
    CHECK(error_of([&] { read_map_file(world); }).first == ErrorKind::Limit);
    CHECK(error_of([&] { SvgDocument::load(world); }).first == ErrorKind::Limit);
    CHECK(error_of([&] { read_png(picture); }).first == ErrorKind::Limit);
}

TEST_CASE("limits: text_bytes bounds the text given to layout_text", "[limits]") {
    const Font font = Font::load(text_test::kDejaVu);
    TextStyle st;
    CHECK_NOTHROW(layout_text("hello world", font, st));
    ScopedLimits s([](Limits& l) { l.text_bytes = 5; });
    auto [kind, msg] = error_of([&] { layout_text("hello world", font, st); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("limit of 5 bytes"));
    CHECK_NOTHROW(layout_text("hello", font, st));
}

TEST_CASE("limits: canvas_save_depth bounds Canvas::save nesting", "[limits]") {
    ScopedLimits s([](Limits& l) { l.canvas_save_depth = 3; });
    Pixmap pm(4, 4);
    Canvas c(pm);
    for (int i = 0; i < 3; ++i) c.save();
    auto [kind, msg] = error_of([&] { c.save(); });
    CHECK(kind == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("more than 3 deep"));
}
