// tests/support/golden.cpp: see golden.hpp.
#include "golden.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "casteljau/error.hpp"
#include "casteljau/png.hpp"

namespace casteljau::golden {

namespace fs = std::filesystem;

namespace {

int channel_diff(PremulPixel a, PremulPixel b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
}

std::string pixel_text(PremulPixel p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%d, %d, %d, %d)", p.r, p.g, p.b, p.a);
    return buf;
}

void write_with_dirs(const Pixmap& pm, const std::string& path) {
    fs::create_directories(fs::path(path).parent_path());
    write_png(pm, path);
}

}  // namespace

std::string Difference::text() const {
    if (size_mismatch) return "sizes differ";
    char buf[200];
    std::snprintf(buf, sizeof buf, "max %d/255, mean %.4f/255; worst pixel (%d, %d): expected %s, actual %s", max_abs,
                  mean_abs, worst_x, worst_y, pixel_text(expected).c_str(), pixel_text(actual).c_str());
    return buf;
}

Difference difference(const Pixmap& expected, const Pixmap& actual) {
    Difference d;
    if (expected.width() != actual.width() || expected.height() != actual.height()) {
        d.size_mismatch = true;
        return d;
    }
    double sum = 0;
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width(); ++x) {
            const PremulPixel e = expected.pixel(x, y), a = actual.pixel(x, y);
            const int v = channel_diff(e, a);
            sum += v;
            if (v > d.max_abs || (x == 0 && y == 0)) {
                d.max_abs = v;
                d.worst_x = x;
                d.worst_y = y;
                d.expected = e;
                d.actual = a;
            }
        }
    const double n = static_cast<double>(actual.width()) * actual.height();
    d.mean_abs = n > 0 ? sum / n : 0.0;
    return d;
}

Pixmap difference_image(const Pixmap& expected, const Pixmap& actual) {
    Pixmap out(actual.width(), actual.height());
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width(); ++x) {
            const PremulPixel e = expected.pixel(x, y), a = actual.pixel(x, y);
            const int v = std::min(255, 8 * channel_diff(e, a));
            const auto faint = static_cast<std::uint8_t>(std::max({e.r, e.g, e.b, e.a}) / 4);
            out.set_pixel(x, y, {static_cast<std::uint8_t>(v), faint, faint, 255});
        }
    return out;
}

Outcome compare_golden(const Setup& setup, const std::string& name, const Pixmap& actual, const Tolerance& tol,
                       const Validation& validated) {
    Outcome o;
    const std::string golden = setup.golden_dir + "/" + name + ".png";
    const std::string actual_out = setup.out_dir + "/" + name + ".actual.png";
    const std::string diff_out = setup.out_dir + "/" + name + ".diff.png";
    const bool exists = fs::exists(golden);
    Pixmap expected;
    std::string previous;
    if (exists) {
        try {
            expected = read_png(golden);
        } catch (const Error& e) { previous = std::string("unreadable golden (") + e.what() + ")"; }
    }
    const Difference d = (exists && previous.empty()) ? difference(expected, actual) : Difference{};
    if (exists && previous.empty()) previous = d.text();

    if (setup.update) {
        if (!validated.passed) {
            o.message = "refusing to write golden " + golden + ": the independent check did not pass (" +
                        validated.summary + ")";
            return o;
        }
        write_with_dirs(actual, golden);
        o.ok = o.wrote_golden = true;
        o.message = "wrote golden " + golden + " (" + validated.summary + "); " +
                    (exists ? "previous golden: " + previous : std::string("it did not exist before"));
        return o;
    }

    auto write_outputs = [&](bool with_diff) {
        write_with_dirs(actual, actual_out);
        if (with_diff) write_with_dirs(difference_image(expected, actual), diff_out);
        o.wrote_outputs = true;
    };
    if (!exists) {
        write_outputs(false);
        o.message = "golden " + golden + " is missing (actual image: " + actual_out +
                    "); create it with CASTELJAU_UPDATE_GOLDEN=1 once the independent check passes";
        return o;
    }
    if (expected.width() == 0) {  // unreadable
        write_outputs(false);
        o.message = "golden " + golden + ": " + previous + " (actual image: " + actual_out + ")";
        return o;
    }
    if (d.size_mismatch) {
        write_outputs(false);
        o.message = "golden " + golden + " is " + std::to_string(expected.width()) + "x" +
                    std::to_string(expected.height()) + ", the actual image " + std::to_string(actual.width()) + "x" +
                    std::to_string(actual.height()) + " (actual image: " + actual_out + ")";
        return o;
    }
    char tolbuf[96];
    std::snprintf(tolbuf, sizeof tolbuf, " (tolerance: max %d, mean %.4f)", tol.max_abs, tol.mean_abs);
    if (d.max_abs > tol.max_abs || d.mean_abs > tol.mean_abs) {
        write_outputs(true);
        o.message = "golden " + name + " differs: " + d.text() + tolbuf + "; wrote " + actual_out + " and " + diff_out;
        return o;
    }
    o.ok = true;
    o.message = "golden " + name + " matches: " + d.text() + tolbuf;
    return o;
}

Setup default_setup() {
    Setup s;
    s.golden_dir = std::string(CASTELJAU_SOURCE_DIR) + "/golden";
    s.out_dir = std::string(CASTELJAU_BINARY_DIR) + "/golden-out";
    const char* env = std::getenv("CASTELJAU_UPDATE_GOLDEN");
    s.update = env != nullptr && std::string(env) == "1";
    return s;
}

bool check_golden(const std::string& name, const Pixmap& actual, const Tolerance& tol, const Validation& validated) {
    const Setup setup = default_setup();
    const Outcome o = compare_golden(setup, name, actual, tol, validated);
    if (setup.update && o.ok) WARN(o.message);
    INFO(o.message);
    CHECK(o.ok);
    return o.ok;
}

}  // namespace casteljau::golden
