// Option parsing helpers shared by the subcommands (see cli.hpp).
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "cli/cli.hpp"
#include "casteljau/limits.hpp"

namespace casteljau::cli {

Color parse_color_option(const std::string& option, const std::string& text) {
    try {
        return parse_color(text);
    } catch (const Error& e) { throw UsageError(option + ": " + e.what()); }
}

void parse_size_option(const std::string& option, const std::string& text, int& width, int& height) {
    const auto x = text.find_first_of("xX");
    auto parse_int = [&](const std::string& s) -> long {
        if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
            throw UsageError(option + ": expected WIDTHxHEIGHT in pixels, got '" + text + "'");
        errno = 0;
        const long v = std::strtol(s.c_str(), nullptr, 10);
        if (errno == ERANGE || v > limits::kMaxCanvasDimension || v < 1)
            throw UsageError(option + ": each side must be 1 to " + std::to_string(limits::kMaxCanvasDimension) +
                             " pixels, got '" + text + "'");
        return v;
    };
    if (x == std::string::npos) throw UsageError(option + ": expected WIDTHxHEIGHT in pixels, got '" + text + "'");
    const long w = parse_int(text.substr(0, x)), h = parse_int(text.substr(x + 1));
    if (static_cast<long long>(w) * h > limits::kMaxCanvasPixels)
        throw UsageError(option + ": " + text + " exceeds the canvas limit of " +
                         std::to_string(limits::kMaxCanvasPixels) + " pixels");
    width = static_cast<int>(w);
    height = static_cast<int>(h);
}

Affine parse_affine_option(const std::string& option, const std::string& text) {
    std::string s = text;
    for (char& c : s)
        if (c == ',') c = ' ';
    std::istringstream in(s);
    double v[6];
    for (double& x : v) {
        if (!(in >> x) || !std::isfinite(x))
            throw UsageError(option + ": expected six finite numbers 'a b c d e f', got '" + text + "'");
    }
    std::string rest;
    if (in >> rest) throw UsageError(option + ": expected six numbers 'a b c d e f', got '" + text + "'");
    return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

std::string read_text_input(const std::string& path) {
    const std::vector<std::uint8_t> bytes = path == "-" ? read_standard_input() : read_file(path);
    return std::string(bytes.begin(), bytes.end());
}

}  // namespace casteljau::cli
