// libFuzzer target: SVG path data and points lists (casteljau/svg_path.hpp), strict and lenient.
// Invariants: the strict parser accepts exactly what the lenient one reads without an error; a
// path that parses formats to path data that parses again to the same verbs.
#include <string>

#include "casteljau/svg_path.hpp"
#include "harness.hpp"

using namespace casteljau;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Bytes in(data, size);
    const std::string_view text = in.rest();
    std::string error;
    const Path lenient = parse_svg_path_lenient(text, &error);
    bool strict_ok = false;
    fuzz::run([&] {
        const Path strict = parse_svg_path(text);
        strict_ok = true;
        fuzz::require(strict.verbs().size() == lenient.verbs().size(), "strict and lenient parses differ");
        fuzz::run([&] {
            const Path again = parse_svg_path(format_svg_path(strict));
            fuzz::require(again.verbs().size() == strict.verbs().size(), "formatted path data reads back differently");
        });
    });
    fuzz::require(strict_ok == error.empty(), "strict parser and lenient error disagree");
    std::string perr;
    (void)parse_points_lenient(text, in.flag(), &perr);
    fuzz::run([&] { (void)parse_points(text); });
    return 0;
}
