// Formats stage: GIF decoding through giflib (decode_gif, include/casteljau/image.hpp).
//
// What is drawn is the first image of the file on its logical screen, as resvg and browsers show
// a GIF that does not animate: the screen starts transparent, the first image's pixels land at its
// offset (those outside the screen are dropped), an interlaced image's rows are put back in order,
// and the transparent colour index of a graphic control extension before the image is
// transparent. Later images (animation frames) are not read, so a file's cost is its first image.
// Sizes are checked against the canvas limits before any pixel buffer is allocated, and against
// the data: LZW codes are at least 3 bits and each stands for at most 4,096 pixels, so a file of
// n bytes cannot describe more than 10,923 n pixels, and a logical screen or an image declared
// larger than that is refused as corrupt before anything is allocated (a tiny image on a huge
// screen is refused too).
#include <gif_lib.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/image.hpp"

namespace casteljau {

namespace {

struct Input {
    std::span<const std::uint8_t> bytes;
    std::size_t at = 0;
};

int read_input(GifFileType* gif, GifByteType* out, int length) {
    auto* in = static_cast<Input*>(gif->UserData);
    const std::size_t n = std::min(static_cast<std::size_t>(std::max(length, 0)), in->bytes.size() - in->at);
    std::memcpy(out, in->bytes.data() + in->at, n);
    in->at += n;
    return static_cast<int>(n);
}

constexpr double kMaxPixelsPerByte = 8.0 / 3.0 * 4096;

// Refuses a declared size larger than the canvas limits or than `bytes` of data can describe.
void check_size(int width, int height, std::size_t bytes) {
    check_canvas_size(width, height);
    if (static_cast<double>(width) * height > kMaxPixelsPerByte * static_cast<double>(bytes))
        throw Error(ErrorKind::InvalidData, "invalid GIF: " + std::to_string(width) + " x " + std::to_string(height) +
                                                " pixels declared in " + std::to_string(bytes) + " bytes");
}

[[noreturn]] void fail(const GifFileType* gif, const char* what) {
    const char* why = gif ? GifErrorString(gif->Error) : nullptr;
    throw Error(ErrorKind::InvalidData,
                std::string("invalid GIF: ") + what + (why ? std::string(" (") + why + ")" : ""));
}

// Closes the file on every path out.
struct GifFile {
    GifFileType* gif = nullptr;
    ~GifFile() {
        int error = 0;
        if (gif) DGifCloseFile(gif, &error);
    }
};

// The transparent colour index of a graphic control extension, or -1.
int transparent_index(int code, const GifByteType* block) {
    if (code != GRAPHICS_EXT_FUNC_CODE || !block || block[0] < 4) return -1;
    return (block[1] & 1) ? block[4] : -1;
}

// Reads the image whose descriptor was just read into `screen`.
void read_image(GifFileType* gif, int transparent, std::size_t bytes, Pixmap& screen) {
    const GifImageDesc& d = gif->Image;
    const ColorMapObject* map = d.ColorMap ? d.ColorMap : gif->SColorMap;
    if (!map) fail(nullptr, "an image without a colour table");
    if (d.Width <= 0 || d.Height <= 0) fail(nullptr, "an image of no size");
    check_size(d.Width, d.Height, bytes);
    std::vector<GifPixelType> line(static_cast<std::size_t>(d.Width));
    // Interlaced images store rows 0, 8, 16, ..., then 4, 12, ..., then 2, 6, ..., then 1, 3, ....
    static constexpr int kStart[4] = {0, 4, 2, 1}, kStep[4] = {8, 8, 4, 2};
    const int passes = d.Interlace ? 4 : 1;
    for (int pass = 0; pass < passes; ++pass)
        for (int y = d.Interlace ? kStart[pass] : 0; y < d.Height; y += d.Interlace ? kStep[pass] : 1) {
            if (DGifGetLine(gif, line.data(), d.Width) == GIF_ERROR) fail(gif, "truncated image data");
            const int sy = d.Top + y;
            if (sy < 0 || sy >= screen.height()) continue;
            for (int x = 0; x < d.Width; ++x) {
                const int sx = d.Left + x;
                const int index = line[static_cast<std::size_t>(x)];
                if (sx < 0 || sx >= screen.width() || index == transparent || index >= map->ColorCount) continue;
                const GifColorType& c = map->Colors[index];
                screen.set_pixel(sx, sy, PremulPixel{c.Red, c.Green, c.Blue, 255});
            }
        }
}

}  // namespace

Pixmap decode_gif(std::span<const std::uint8_t> bytes) {
    Input in{bytes};
    GifFile file;
    int error = 0;
    file.gif = DGifOpen(&in, read_input, &error);
    if (!file.gif) {
        const char* why = GifErrorString(error);
        throw Error(ErrorKind::InvalidData,
                    std::string("invalid GIF: cannot read its header") + (why ? std::string(" (") + why + ")" : ""));
    }
    GifFileType* gif = file.gif;
    if (gif->SWidth <= 0 || gif->SHeight <= 0) fail(nullptr, "a logical screen of no size");
    check_size(gif->SWidth, gif->SHeight, bytes.size());
    Pixmap screen(gif->SWidth, gif->SHeight);
    int transparent = -1;
    for (;;) {
        GifRecordType type = UNDEFINED_RECORD_TYPE;
        if (DGifGetRecordType(gif, &type) == GIF_ERROR) fail(gif, "truncated data");
        if (type == TERMINATE_RECORD_TYPE) fail(nullptr, "no image");
        if (type == EXTENSION_RECORD_TYPE) {
            int code = 0;
            GifByteType* block = nullptr;
            if (DGifGetExtension(gif, &code, &block) == GIF_ERROR) fail(gif, "truncated extension");
            if (const int t = transparent_index(code, block); code == GRAPHICS_EXT_FUNC_CODE) transparent = t;
            while (block)
                if (DGifGetExtensionNext(gif, &block) == GIF_ERROR) fail(gif, "truncated extension");
            continue;
        }
        if (type != IMAGE_DESC_RECORD_TYPE) fail(nullptr, "an unknown record");
        if (DGifGetImageDesc(gif) == GIF_ERROR) fail(gif, "truncated image descriptor");
        read_image(gif, transparent, bytes.size(), screen);
        return screen;
    }
}

}  // namespace casteljau
