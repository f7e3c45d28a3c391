// Tests for the curve commands of the CLI (src/cli/cmd_bezier.cpp, cmd_spline.cpp): they run the
// built binary (CASTELJAU_CLI_PATH) and check its standard output and exit status.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "temp_dir.hpp"

namespace {

struct Run {
    int status = -1;
    std::string out;
};

// Runs the CLI with `args` (shell syntax); stderr is discarded.
Run run(const std::string& args) {
    const std::string cmd = std::string("'") + CASTELJAU_CLI_PATH + "' " + args + " 2>/dev/null";
    Run r;
    FILE* p = popen(cmd.c_str(), "r");
    REQUIRE(p != nullptr);
    char buf[4096];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
    const int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return r;
}

std::string temp_file(const std::string& name, const std::string& content) {
    const auto path = casteljau::testing::process_temp_dir() / ("curves_" + name);
    std::ofstream(path) << content;
    return path.string();
}

}  // namespace

TEST_CASE("CLI bezier: the textbook worked numbers", "[curves-cli]") {
    const std::string cubic = "--points '0,0 48,96 120,120 216,72'";
    Run r = run("bezier " + cubic + " --eval 0.4");
    CHECK(r.status == 0);
    CHECK(r.out == "69.12 80.64\n");
    r = run("bezier " + cubic + " --power");
    CHECK(r.out == "0 0\n144 288\n72 -216\n0 0\n");
    r = run("bezier --points '0,0 0,100 100,0 100,100' --elevate");
    CHECK(r.status == 0);
    CHECK(r.out == "0 0\n0 75\n50 50\n100 25\n100 100\n");
    r = run("bezier --points '30,0 60,10 80,30 90,60 90,90' --triangle 0.5");
    CHECK(r.status == 0);
    CHECK(r.out ==
          "30 0\n60 10\n80 30\n90 60\n90 90\n\n45 5\n70 20\n85 45\n90 75\n\n57.5 12.5\n77.5 32.5\n87.5 60\n\n"
          "67.5 22.5\n82.5 46.25\n\n75 34.375\n");
    r = run("bezier --points '50,0 100,0 0,50 0,100' --interpolate");
    CHECK(r.status == 0);
    CHECK(r.out == "50 0\n258.333333333 -41.6666666667\n-133.333333333 66.6666666667\n0 100\n");
}

TEST_CASE("CLI bezier: split, derivative, reduce, bounds, 3-D, JSON file", "[curves-cli]") {
    Run r = run("bezier --points '0,0 0,100 100,100 100,0' --split 0.5");
    CHECK(r.out == "0 0\n0 50\n25 75\n50 75\n\n50 75\n75 75\n100 50\n100 0\n");
    r = run("bezier --points '0,0 0,100 100,100 100,0' --derivative 1 --eval 0");
    CHECK(r.out == "0 300\n");
    r = run("bezier --points '0,0 0,100 100,100 100,0' --derivative 1");
    CHECK(r.out == "0 300\n300 0\n0 -300\n");
    r = run("bezier --points '0,0 0,100 100,100 100,0' --bounds");
    CHECK(r.out == "0 0\n100 75\n");
    // Reducing the elevated curve gives the original back.
    r = run("bezier --points '0,0 0,75 50,50 100,25 100,100' --reduce");
    CHECK(r.status == 0);
    CHECK(r.out == "0 0\n0 100\n100 0\n100 100\n");
    r = run("bezier --points '0,0,0 10,10,10 20,0,20' --eval 0.5");
    CHECK(r.out == "10 5 10\n");
    const std::string f = temp_file("cubic.json", R"({"points": [[0, 0], [48, 96], [120, 120], [216, 72]]})");
    r = run("bezier --points-file '" + f + "' --eval 0.4");
    CHECK(r.status == 0);
    CHECK(r.out == "69.12 80.64\n");
    CHECK(run("bezier --help").status == 0);
}

TEST_CASE("CLI bezier: bad input exits 1 for data and 2 for usage", "[curves-cli]") {
    CHECK(run("bezier --points '1,2' --eval 0.5").status == 1);  // fewer than 2 points
    CHECK(run("bezier --points '' --eval 0.5").status == 1);
    std::string many;
    for (int i = 0; i < 1001; ++i) many += std::to_string(i) + ",0 ";
    CHECK(run("bezier --points '" + many + "' --eval 0.5").status == 1);  // degree 1000
    CHECK(run("bezier --points '0,0 1,1' --eval 1.5").status == 2);       // t outside [0, 1]
    CHECK(run("bezier --points '0,0 1,1' --eval -0.1").status == 2);
    CHECK(run("bezier --points '0,0 1,x' --eval 0.5").status == 2);    // malformed
    CHECK(run("bezier --points '0,0 1,1,1' --eval 0.5").status == 2);  // mixed dimensions
    CHECK(run("bezier --points '0,0 1,1'").status == 2);               // no action
    CHECK(run("bezier --points '0,0 1,1' --eval 0.5 --elevate").status == 2);
    CHECK(run("bezier --eval 0.5").status == 2);  // no points
    CHECK(run("bezier --points '0,0 1,1' --bogus").status == 2);
    CHECK(run("bezier --points '0,0 1,1' --reduce").status == 2);  // a line cannot be reduced
    CHECK(run("bezier --points-file /nonexistent/x.json --eval 0.5").status == 1);
    const std::string bad = temp_file("bad.json", R"({"points": [[0, 0], [1]]})");
    CHECK(run("bezier --points-file '" + bad + "' --eval 0.5").status == 1);
    const std::string broken = temp_file("broken.json", R"({"points": [[0, 0], )");
    CHECK(run("bezier --points-file '" + broken + "' --eval 0.5").status == 1);
}

TEST_CASE("CLI spline: Bezier pieces and evaluation", "[curves-cli]") {
    // One uniform cubic B-spline segment: the textbook matrix (D0 + 4 D1 + D2)/6, ...
    Run r = run("spline --kind bspline --points '0,0 6,0 6,6 0,6' --knot-type uniform --to-bezier");
    CHECK(r.status == 0);
    CHECK(r.out == "5 1\n6 2\n6 4\n5 5\n");
    r = run("spline --kind bspline --points '0,0 10,20 30,20 40,0' --degree 2 --to-bezier");
    CHECK(r.out == "0 0\n10 20\n20 20\n\n20 20\n30 20\n40 0\n");
    r = run("spline --kind nurbs --points '1,0 1,1 0,1' --weights '1 0.7071067811865476 1' --degree 2 --eval 0.5");
    CHECK(r.out == "0.707106781187 0.707106781187\n");
    r = run("spline --kind catmull-rom --points '0,0 10,10 20,0' --to-bezier");
    CHECK(r.out ==
          "0 0\n1.66666666667 1.66666666667\n6.66666666667 10\n10 10\n\n10 10\n13.3333333333 10\n18.3333333333 "
          "1.66666666667\n20 0\n");
    r = run("spline --kind natural --points '0,0 1,2 2,4 3,6' --eval 1.5");
    CHECK(r.out == "1.5 3\n");
    r = run("spline --kind hermite --points '0,0 10,0' --tangents '30,0 0,30' --to-bezier");
    CHECK(r.out == "0 0\n10 0\n10 -10\n10 0\n");
    r = run("spline --kind kb --points '0,0 10,10 20,0 30,10' --continuity -1 --to-bezier");
    CHECK(r.status == 0);
    r = run("spline --kind bspline --points '0,0 1,1 2,0 3,1' --basis-at 0.5");
    CHECK(r.out == "0.125\n0.375\n0.375\n0.125\n");
    const std::string f =
        temp_file("nurbs.json", R"({"points": [[1, 0], [1, 1], [0, 1]], "weights": [1, 0.5, 1], "degree": 2})");
    r = run("spline --kind nurbs --points-file '" + f + "' --to-bezier");
    CHECK(r.out == "1 0 1\n1 1 0.5\n0 1 1\n");
}

TEST_CASE("CLI spline: bad input exits 1 for data and 2 for usage", "[curves-cli]") {
    CHECK(run("spline --kind bspline --points '0,0' --degree 1 --to-bezier").status == 1);  // fewer than 2 points
    CHECK(run("spline --kind natural --points '0,0' --to-bezier").status == 1);
    CHECK(run("spline --kind bspline --points '0,0 1,1 2,2' --degree 1 --knots '0 0 1 1' --to-bezier").status == 1);
    CHECK(run("spline --kind bspline --points '0,0 1,1 2,2' --degree 1 --knots '0 0 2 1 1' --to-bezier").status == 1);
    CHECK(run("spline --kind nurbs --points '0,0 1,1 2,2' --degree 1 --weights '1 0 1' --to-bezier").status == 1);
    CHECK(run("spline --kind nurbs --points '0,0 1,1 2,2' --degree 1 --weights '1 -1 1' --to-bezier").status == 1);
    CHECK(run("spline --kind nurbs --points '0,0 1,1 2,2' --degree 1 --weights '1 1' --to-bezier").status == 1);
    CHECK(run("spline --kind bspline --points '0,0 1,1' --degree 0 --to-bezier").status == 2);
    CHECK(run("spline --kind bspline --points '0,0 1,1' --degree 1000 --to-bezier").status == 2);
    const std::string f = temp_file("deg.json", R"({"points": [[0, 0], [1, 1]], "degree": 1000})");
    CHECK(run("spline --kind bspline --points-file '" + f + "' --to-bezier").status == 1);
    CHECK(run("spline --kind bspline --points '0,0 1,1 2,0 3,1' --eval 1.5").status == 2);  // outside the domain
    CHECK(run("spline --kind catmull-rom --points '0,0 1,1 2,0' --eval 5").status == 2);
    CHECK(run("spline --kind wobbly --points '0,0 1,1' --to-bezier").status == 2);
    CHECK(run("spline --kind bspline --points '0,0 1,1' --weights '1 1' --to-bezier").status == 2);
    CHECK(run("spline --kind bspline --points '0,0 1,1' --degree 1").status == 2);  // no action
    CHECK(run("spline --points '0,0 1,1' --to-bezier").status == 2);                // no kind
    CHECK(run("spline --kind hermite --points '0,0 1,1' --tangents '1,0' --to-bezier").status == 1);
}
