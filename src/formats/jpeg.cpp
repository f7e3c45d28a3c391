// Formats stage: JPEG decoding through libjpeg(-turbo) (decode_jpeg, include/casteljau/image.hpp).
// libjpeg reports fatal errors through a longjmp out of its error handler; the setjmp scope holds
// no C++ objects with destructors.
// jpeglib.h needs size_t and FILE declared first.
#include <cstddef>
#include <cstdio>
#include <jpeglib.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <csetjmp>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/image.hpp"

namespace casteljau {

namespace {

struct ErrorManager {
    jpeg_error_mgr pub;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void on_error(j_common_ptr cinfo) {
    auto* err = reinterpret_cast<ErrorManager*>(cinfo->err);
    (*cinfo->err->format_message)(cinfo, err->message);
    std::longjmp(err->jump, 1);
}

void on_message(j_common_ptr, int) {}

// Reads the header; false with the message set on a libjpeg error.
bool read_header(jpeg_decompress_struct* cinfo, ErrorManager* err, const std::uint8_t* data, std::size_t size) {
    if (setjmp(err->jump)) return false;
    jpeg_mem_src(cinfo, data, static_cast<unsigned long>(size));
    jpeg_read_header(cinfo, TRUE);
    if (cinfo->jpeg_color_space == JCS_CMYK || cinfo->jpeg_color_space == JCS_YCCK)
        cinfo->out_color_space = JCS_CMYK;
    else if (cinfo->jpeg_color_space == JCS_GRAYSCALE)
        cinfo->out_color_space = JCS_GRAYSCALE;
    else
        cinfo->out_color_space = JCS_RGB;
    jpeg_calc_output_dimensions(cinfo);
    return true;
}

// Decodes the scanlines into `pm` (opaque, so premultiplied equals straight); false on a libjpeg error.
bool read_pixels(jpeg_decompress_struct* cinfo, ErrorManager* err, Pixmap& pm, std::uint8_t* row) {
    if (setjmp(err->jump)) return false;
    jpeg_start_decompress(cinfo);
    const unsigned w = cinfo->output_width;
    const int comps = cinfo->output_components;
    while (cinfo->output_scanline < cinfo->output_height) {
        const unsigned y = cinfo->output_scanline;
        JSAMPROW rows[1] = {row};
        jpeg_read_scanlines(cinfo, rows, 1);
        std::uint8_t* d = pm.row(static_cast<int>(y));
        for (unsigned x = 0; x < w; ++x, d += 4) {
            const std::uint8_t* s = row + static_cast<std::size_t>(x) * comps;
            if (comps == 1) {
                d[0] = d[1] = d[2] = s[0];
            } else if (comps == 4) {
                // Adobe CMYK JPEGs store inverted values: R = C' x K' / 255.
                d[0] = static_cast<std::uint8_t>(s[0] * s[3] / 255);
                d[1] = static_cast<std::uint8_t>(s[1] * s[3] / 255);
                d[2] = static_cast<std::uint8_t>(s[2] * s[3] / 255);
            } else {
                d[0] = s[0];
                d[1] = s[1];
                d[2] = s[2];
            }
            d[3] = 255;
        }
    }
    jpeg_finish_decompress(cinfo);
    return true;
}

}  // namespace

Pixmap decode_jpeg(std::span<const std::uint8_t> bytes) {
    if (bytes.empty()) throw Error(ErrorKind::InvalidData, "JPEG data is empty");
    jpeg_decompress_struct cinfo{};
    ErrorManager err{};
    cinfo.err = jpeg_std_error(&err.pub);
    err.pub.error_exit = on_error;
    err.pub.emit_message = on_message;
    jpeg_create_decompress(&cinfo);
    if (!read_header(&cinfo, &err, bytes.data(), bytes.size())) {
        jpeg_destroy_decompress(&cinfo);
        throw Error(ErrorKind::InvalidData, std::string("corrupt JPEG: ") + err.message);
    }
    const double w = cinfo.output_width, h = cinfo.output_height;
    // Huffman coding spends at least one bit on each 8x8 block of a component (its DC difference),
    // so a file shorter than its largest component's blocks / 8 bytes cannot hold its image: it is
    // a header with (most of) the data missing, which libjpeg would pad out to any declared size.
    // Refuse it before allocating the image. (Arithmetic coding can go below a bit per block; no
    // browser decodes it, and such files are held to the same bound.)
    double blocks = 0;
    for (int c = 0; c < cinfo.num_components; ++c)
        blocks = std::max(blocks, static_cast<double>(cinfo.comp_info[c].width_in_blocks) *
                                      static_cast<double>(cinfo.comp_info[c].height_in_blocks));
    if (blocks > 8.0 * static_cast<double>(bytes.size())) {
        const std::string msg =
            "corrupt JPEG: " + std::to_string(cinfo.image_width) + "x" + std::to_string(cinfo.image_height) +
            " pixels need at least " + std::to_string(static_cast<long long>(std::ceil(blocks / 8))) +
            " bytes of coded data, the file has " + std::to_string(bytes.size()) + " (truncated, or a corrupt size)";
        jpeg_destroy_decompress(&cinfo);
        throw Error(ErrorKind::InvalidData, msg);
    }
    std::optional<Pixmap> pm;
    std::vector<std::uint8_t> row;
    try {
        check_canvas_size(w, h);
        pm.emplace(static_cast<int>(w), static_cast<int>(h));
        row.resize(static_cast<std::size_t>(w) * 4);
    } catch (...) {
        jpeg_destroy_decompress(&cinfo);
        throw;
    }
    // libjpeg's own working memory (whole-image coefficient buffers of progressive files) is
    // bounded too: past it, decoding stops with "insufficient memory".
    cinfo.mem->max_memory_to_use =
        static_cast<long>(std::min<std::uint64_t>(current_limits().jpeg_working_memory, LONG_MAX));
    const bool ok = read_pixels(&cinfo, &err, *pm, row.data());
    jpeg_destroy_decompress(&cinfo);
    if (!ok) throw Error(ErrorKind::InvalidData, std::string("corrupt JPEG: ") + err.message);
    return std::move(*pm);
}

}  // namespace casteljau
