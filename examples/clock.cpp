// example_clock: a clock face drawn with cubic Bézier arcs (see clock_face.hpp), written as a PNG.
//
//   example_clock [HH:MM:SS] [OUT.png] [SIZE]      defaults: 10:08:30 clock.png 400
//
// Exit status 0 on success, 1 when the file cannot be written, 2 for bad arguments.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "casteljau/png.hpp"
#include "clock_face.hpp"

int main(int argc, char** argv) {
    clock_face::Time t;
    std::string out = "clock.png";
    int size = 400;
    if (argc > 4 || (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))) {
        std::fprintf(stderr, "usage: example_clock [HH:MM:SS] [OUT.png] [SIZE]   (default 10:08:30 clock.png 400)\n");
        return argc > 4 ? 2 : 0;
    }
    if (argc > 1 && !clock_face::parse_time(argv[1], t)) {
        std::fprintf(stderr, "example_clock: error: expected HH:MM:SS (00:00:00 to 23:59:59), got '%s'\n", argv[1]);
        return 2;
    }
    if (argc > 2) out = argv[2];
    if (argc > 3) {
        char* end = nullptr;
        const long v = std::strtol(argv[3], &end, 10);
        if (*end != '\0' || v < 32 || v > 4096) {
            std::fprintf(stderr, "example_clock: error: SIZE must be 32 to 4096 pixels, got '%s'\n", argv[3]);
            return 2;
        }
        size = static_cast<int>(v);
    }
    try {
        casteljau::write_png(clock_face::draw(t, size), out);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "example_clock: error: %s\n", e.what());
        return 1;
    }
    std::printf("%s\n", out.c_str());
    return 0;
}
