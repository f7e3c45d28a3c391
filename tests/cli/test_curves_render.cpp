// Tests for the picture paths of the curve commands: bezier --render/--construction, spline
// --render/--basis, and the surface command. They run the built binary (CASTELJAU_CLI_PATH), check
// exit statuses and one-line errors, that failures leave no file, and that the PNG written is
// pixel-for-pixel the library's drawing of the same input (figures.hpp, which the golden tests
// check in detail).
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "casteljau/figures.hpp"
#include "casteljau/png.hpp"
#include "casteljau/spline.hpp"
#include "cli_util.hpp"

using namespace casteljau;
using casteljau::test::run_cli;
using casteljau::test::scratch_dir;
using casteljau::test::shell_quote;

namespace {

namespace fs = std::filesystem;

// The largest per-channel difference between a PNG file and a Pixmap (after the same PNG round trip).
int max_difference(const std::string& png_file, const Pixmap& expected) {
    const Pixmap a = read_png(png_file);
    const Pixmap b = decode_png(encode_png(expected));
    if (a.width() != b.width() || a.height() != b.height()) return 256;
    int m = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < 4 * a.width(); ++x) m = std::max(m, std::abs(a.row(y)[x] - b.row(y)[x]));
    return m;
}

bool one_line_error(const std::string& err) {
    return err.rfind("casteljau: error: ", 0) == 0 && std::count(err.begin(), err.end(), '\n') == 1;
}

std::string write_text(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
    return p.string();
}

const std::string kCubic = "--points '0,0 48,96 120,120 216,72'";

}  // namespace

TEST_CASE("bezier --render draws the library's figure, --construction adds the construction", "[curves-render]") {
    const fs::path dir = scratch_dir("bezier-render");
    const Bezier<Point> curve{{0, 0}, {48, 96}, {120, 120}, {216, 72}};
    const std::string plain = (dir / "plain.png").string(), built = (dir / "built.png").string();

    auto r = run_cli("bezier " + kCubic + " --render " + shell_quote(plain));
    REQUIRE(r.status == 0);
    CHECK(r.out.empty());
    CHECK(max_difference(plain, draw_bezier_figure(curve, {}).image) == 0);

    r = run_cli("bezier " + kCubic + " --render " + shell_quote(built) + " --construction 0.4 --size 300x200");
    REQUIRE(r.status == 0);
    FigureOptions o{300, 200, 20};  // the CLI's margin: min(24, shorter side / 10)
    CHECK(max_difference(built, draw_bezier_figure(curve, o, 0.4).image) == 0);
    // The construction changes the picture (the highlight is there).
    const Pixmap with = read_png(built);
    const Figure f = draw_bezier_figure(curve, o, 0.4);
    const Point pt = f.transform.apply(curve.eval(0.4));
    const Color c = unpremultiply(with.pixel(static_cast<int>(pt.x), static_cast<int>(pt.y)));
    CHECK(c == figure_colors::kHighlight);
}

TEST_CASE("bezier --render errors: exit status, one line, no file", "[curves-render]") {
    const fs::path dir = scratch_dir("bezier-render-errors");
    const std::string out = (dir / "x.png").string();
    struct Case {
        std::string args;
        int status;
    };
    for (const Case& c : std::initializer_list<Case>{
             {"bezier " + kCubic + " --render " + shell_quote(out) + " --construction 1.5", 2},
             {"bezier " + kCubic + " --render " + shell_quote(out) + " --construction -0.1", 2},
             {"bezier " + kCubic + " --construction 0.5", 2},         // without --render
             {"bezier " + kCubic + " --size 100x100 --eval 0.5", 2},  // --size without --render
             {"bezier " + kCubic + " --render " + shell_quote(out) + " --size 0x10", 2},
             {"bezier " + kCubic + " --render " + shell_quote(out) + " --size big", 2},
             {"bezier " + kCubic + " --render " + shell_quote(out) + " --eval 0.5", 2},  // two actions
             {"bezier --points '0,0,0 1,1,1' --render " + shell_quote(out), 2},          // 3-D
             {"bezier --points '0,0' --render " + shell_quote(out), 1},                  // one point
             {"bezier " + kCubic + " --render " + shell_quote((dir / "no" / "such" / "x.png").string()), 1},
         }) {
        INFO(c.args);
        const auto r = run_cli(c.args);
        CHECK(r.status == c.status);
        CHECK(one_line_error(r.err));
        CHECK(!fs::exists(out));
    }
}

TEST_CASE("spline --render and --basis draw the library's figures", "[curves-render]") {
    const fs::path dir = scratch_dir("spline-render");
    const std::string curve_png = (dir / "s.png").string(), basis_png = (dir / "b.png").string();
    const auto r =
        run_cli("spline --kind bspline --degree 3 --points '0,60 40,0 90,20 120,90 170,100 200,30 240,50' --render " +
                shell_quote(curve_png) + " --basis " + shell_quote(basis_png));
    REQUIRE(r.status == 0);
    const BSpline<Point> s =
        BSpline<Point>::clamped(3, {{0, 60}, {40, 0}, {90, 20}, {120, 90}, {170, 100}, {200, 30}, {240, 50}});
    std::vector<Point> knots;
    for (double u : s.breakpoints()) knots.push_back(s.eval(u));
    CHECK(max_difference(curve_png, draw_spline_figure(to_path(s.to_bezier()), s.points(), knots, {}).image) == 0);
    CHECK(max_difference(basis_png, draw_basis_figure(3, s.knots(), {}).image) == 0);

    // Explicit knots with a double knot, and a non-square size.
    const std::string b2 = (dir / "b2.png").string();
    REQUIRE(
        run_cli("spline --kind bspline --degree 2 --knots '0 0 0 1 2 2 3 4 4 4' --points '0,0 1,2 2,0 3,2 4,0 5,2 6,0' "
                "--basis " +
                shell_quote(b2) + " --size 480x240")
            .status == 0);
    CHECK(max_difference(
              b2, draw_basis_figure(2, std::vector<double>{0, 0, 0, 1, 2, 2, 3, 4, 4, 4}, {480, 240, 24}).image) == 0);

    // Interpolating kinds render too (their Bézier control polygon, the data points as knots).
    const std::string cr = (dir / "cr.png").string();
    REQUIRE(run_cli("spline --kind catmull-rom --points '0,50 40,0 90,40 130,10' --render " + shell_quote(cr)).status ==
            0);
    CHECK(read_png(cr).width() == 400);
    // NURBS: a quarter circle.
    const std::string nu = (dir / "nurbs.png").string();
    REQUIRE(run_cli("spline --kind nurbs --degree 2 --points '100,0 100,100 0,100' --weights '1 0.7071067811865476 1' "
                    "--render " +
                    shell_quote(nu))
                .status == 0);
    CHECK(read_png(nu).height() == 400);
}

TEST_CASE("spline --render/--basis errors", "[curves-render]") {
    const fs::path dir = scratch_dir("spline-render-errors");
    const std::string out = (dir / "x.png").string();
    struct Case {
        std::string args;
        int status;
    };
    for (const Case& c : std::initializer_list<Case>{
             {"spline --kind catmull-rom --points '0,0 1,1 2,0' --basis " + shell_quote(out), 2},  // no basis for it
             {"spline --kind bspline --points '0,0,0 1,1,1 2,0,0 3,1,1' --render " + shell_quote(out), 2},
             {"spline --kind bspline --points '0,0 1,1 2,0 3,1' --render " + shell_quote(out) + " --eval 0.5", 2},
             {"spline --kind bspline --points '0,0 1,1 2,0 3,1' --size 10x10 --eval 0.5", 2},
             {"spline --kind bspline --degree 3 --knots '0 0 0 1 1 1' --points '0,0 1,1 2,0 3,1' --basis " +
                  shell_quote(out),
              1},
             {"spline --kind bspline --degree 2 --knots '0 0 0 2 1 1 1' --points '0,0 1,1 2,0 3,1' --render " +
                  shell_quote(out),
              1},
         }) {
        INFO(c.args);
        const auto r = run_cli(c.args);
        CHECK(r.status == c.status);
        CHECK(one_line_error(r.err));
        CHECK(!fs::exists(out));
    }
}

TEST_CASE("surface --render draws the shipped patch as the library does", "[surface-cli]") {
    const fs::path dir = scratch_dir("surface-render");
    const std::string patch = std::string(CASTELJAU_SOURCE_DIR) + "/examples/data/patch.json";
    std::vector<Point3> net;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const bool ii = i == 1 || i == 2, jj = j == 1 || j == 2;
            net.push_back({100.0 * i, ii && jj ? -160.0 : (ii || jj ? -20.0 : 0.0), 100.0 * j});
        }
    const BezierPatch<Point3> s(3, 3, net);
    struct Case {
        std::string opts;
        Projection projection;
        int grid;
        bool shaded;
    };
    for (const Case& c :
         std::initializer_list<Case>{{"", Projection::Cavalier, 10, false},
                                     {"--projection cabinet --grid 12", Projection::Cabinet, 12, false},
                                     {"--projection ortho --grid 4", Projection::Orthographic, 4, false},
                                     {"--shaded --grid 6", Projection::Cavalier, 6, true}}) {
        INFO(c.opts);
        const std::string out = (dir / "s.png").string();
        const auto r = run_cli("surface " + shell_quote(patch) + " --render " + shell_quote(out) + " " + c.opts);
        REQUIRE(r.status == 0);
        SurfaceDrawing d;
        d.projection = c.projection;
        d.grid = c.grid;
        d.shaded = c.shaded;
        CHECK(max_difference(out, draw_surface_figure(s, d, {}).image) == 0);
    }
    // The projections differ from each other.
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string();
    REQUIRE(run_cli("surface " + shell_quote(patch) + " --render " + shell_quote(a) + " --projection ortho").status ==
            0);
    REQUIRE(run_cli("surface " + shell_quote(patch) + " --render " + shell_quote(b) + " --projection cabinet").status ==
            0);
    CHECK(max_difference(a, read_png(b)) > 100);
}

TEST_CASE("surface: B-spline and NURBS surfaces from JSON", "[surface-cli]") {
    const fs::path dir = scratch_dir("surface-spline");
    const std::string grid =
        "[[[0,0,0],[0,-10,50],[0,0,100],[0,-10,150]],[[50,-10,0],[50,-60,50],[50,-60,100],[50,-10,150]],"
        "[[100,0,0],[100,-60,50],[100,-60,100],[100,0,150]],[[150,-10,0],[150,-10,50],[150,0,100],[150,-10,150]],"
        "[[200,0,0],[200,0,50],[200,-10,100],[200,0,150]]]";
    const std::string bs =
        write_text(dir / "bs.json", R"({"type": "bspline", "degree": [2, 3], "points": )" + grid + "}");
    const std::string out = (dir / "bs.png").string();
    REQUIRE(run_cli("surface " + shell_quote(bs) + " --render " + shell_quote(out)).status == 0);
    std::vector<Point3> net;
    const double ys[5][4] = {
        {0, -10, 0, -10}, {-10, -60, -60, -10}, {0, -60, -60, 0}, {-10, -10, 0, -10}, {0, 0, -10, 0}};
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j) net.push_back({50.0 * i, ys[i][j], 50.0 * j});
    CHECK(max_difference(out, draw_surface_figure(BSplineSurface<Point3>::clamped(2, 3, 5, 4, net), {}, {}).image) ==
          0);

    const std::string nu =
        write_text(dir / "nu.json", R"({"type": "nurbs", "degree": [2, 3], "points": )" + grid +
                                        R"(, "weights": [[1,1,1,1],[1,2,2,1],[1,2,2,1],[1,1,1,1],[1,1,1,1]]})");
    REQUIRE(run_cli("surface " + shell_quote(nu) + " --render " + shell_quote(out)).status == 0);
    CHECK(read_png(out).width() == 400);
}

TEST_CASE("surface errors: bad files exit 1 with one line, bad options exit 2, no file", "[surface-cli]") {
    const fs::path dir = scratch_dir("surface-errors");
    const std::string out = (dir / "x.png").string();
    const std::string patch = std::string(CASTELJAU_SOURCE_DIR) + "/examples/data/patch.json";
    struct Case {
        std::string file_text;  // empty: use the shipped patch
        std::string opts;
        int status;
    };
    const std::string row3 = "[[0,0,0],[1,0,0],[2,0,0]]";
    for (const Case& c : std::initializer_list<Case>{
             {"{\"degree\": [3, 3], \"points\": [", "", 1},                                    // malformed JSON
             {"[1, 2]", "", 1},                                                                // not an object
             {"{\"points\": [" + row3 + "," + row3 + "]}", "", 1},                             // no degree
             {"{\"degree\": [2, 2], \"points\": [" + row3 + "," + row3 + "]}", "", 1},         // 2 rows for m = 2
             {"{\"degree\": [1, 1], \"points\": [" + row3 + "," + row3 + "]}", "", 1},         // 3 columns for n = 1
             {"{\"degree\": [1, 2], \"points\": [" + row3 + ",[[0,0,0],[1,0,0]]]}", "", 1},    // ragged
             {"{\"degree\": [1, 2], \"points\": [" + row3 + ",[[0,0],[1,0],[2,0]]]}", "", 1},  // 2-D point
             {"{\"degree\": [1, 2], \"points\": [" + row3 + ",[[0,0,0],[1,\"a\",0],[2,0,0]]]}", "", 1},
             {"{\"degree\": [0, 2], \"points\": [" + row3 + "]}", "", 1},     // degree 0
             {"{\"degree\": [1000, 2], \"points\": [" + row3 + "]}", "", 1},  // absurd degree
             {"{\"type\": \"coons\", \"degree\": [1, 2], \"points\": [" + row3 + "," + row3 + "]}", "", 1},
             {"{\"type\": \"bspline\", \"degree\": [1, 2], \"points\": [" + row3 + "," + row3 +
                  "], \"knots_u\": [0, 1]}",
              "", 1},
             {"{\"type\": \"nurbs\", \"degree\": [1, 2], \"points\": [" + row3 + "," + row3 +
                  "], \"weights\": [[1,1,1],[1,0,1]]}",
              "", 1},
             {"", "--projection isometric", 2},
             {"", "--grid 1", 2},
             {"", "--grid 5000", 2},
             {"", "--size 3", 2},
         }) {
        const std::string file = c.file_text.empty() ? patch : write_text(dir / "in.json", c.file_text);
        INFO(c.file_text << " " << c.opts);
        const auto r = run_cli("surface " + shell_quote(file) + " --render " + shell_quote(out) + " " + c.opts);
        CHECK(r.status == c.status);
        CHECK(one_line_error(r.err));
        CHECK(!fs::exists(out));
    }
    // A missing input file, and a missing --render.
    auto r = run_cli("surface " + shell_quote((dir / "missing.json").string()) + " --render " + shell_quote(out));
    CHECK(r.status == 1);
    CHECK(one_line_error(r.err));
    r = run_cli("surface " + shell_quote(patch));
    CHECK(r.status == 2);
    CHECK(!fs::exists(out));
}
