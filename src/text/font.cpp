// Text stage, source end: fonts through FreeType (include/casteljau/font.hpp).
//
// Font file bytes --(sfnt directory check)--> FreeType face sized at units_per_em px --> unhinted
// outlines decomposed into Paths (font units, y up) and metrics; an hb-ft HarfBuzz font on the same
// face serves shaping (src/text/shape.cpp).
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_FONT_FORMATS_H
#include FT_MULTIPLE_MASTERS_H
#include FT_OUTLINE_H
#include FT_BBOX_H
#include FT_SFNT_NAMES_H
#include FT_TRUETYPE_IDS_H
#include FT_TRUETYPE_TABLES_H
#include <hb-ft.h>
#include <hb-ot.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <sstream>

#include "casteljau/limits.hpp"
#include "text/color_glyphs.hpp"
#include "text/font_impl.hpp"

namespace casteljau {

namespace {

std::string ft_error_text(FT_Error err) {
    if (const char* s = FT_Error_String(err)) return s;
    std::ostringstream o;
    o << "FreeType error 0x" << std::hex << err;
    return o.str();
}

[[noreturn]] void font_error(const std::string& source, const std::string& what) {
    throw Error(ErrorKind::Font, "font '" + source + "': " + what);
}

std::string tag_string(std::uint32_t tag) {
    std::string s(4, ' ');
    for (int i = 0; i < 4; ++i) {
        const char c = static_cast<char>((tag >> (24 - 8 * i)) & 0xff);
        s[static_cast<std::size_t>(i)] = (c >= 0x20 && c < 0x7f) ? c : '?';
    }
    return s;
}

void check_face_index(int face_index, const std::string& name) {
    if (face_index < 0 || face_index > 0xffff)
        throw Error(ErrorKind::InvalidArgument,
                    "font '" + name + "': face index must be 0 to 65535, got " + std::to_string(face_index));
}

// Checks the table directory of an sfnt (TrueType/OpenType) file or collection against the file
// size, so that a truncated font is reported as such instead of failing later in odd ways.
// Files of other formats (Type 1, WOFF, ...) are left to FreeType.
void check_sfnt_directory(const std::uint8_t* b, std::size_t n, const std::string& source) {
    if (n < 12) font_error(source, "not a font file (only " + std::to_string(n) + " bytes)");
    auto u16 = [&](std::size_t o) { return static_cast<std::uint32_t>(b[o] << 8 | b[o + 1]); };
    auto u32 = [&](std::size_t o) {
        return static_cast<std::uint32_t>(b[o]) << 24 | static_cast<std::uint32_t>(b[o + 1]) << 16 |
               static_cast<std::uint32_t>(b[o + 2]) << 8 | static_cast<std::uint32_t>(b[o + 3]);
    };
    auto truncated = [&](const std::string& what) {
        font_error(source, "truncated or corrupt font file: " + what + " runs past the end of the file (" +
                               std::to_string(n) + " bytes)");
    };
    auto check_dir = [&](std::uint64_t off) {
        if (off + 12 > n) truncated("the table directory");
        const std::uint32_t tables = u16(static_cast<std::size_t>(off) + 4);
        if (off + 12 + 16ull * tables > n) truncated("the table directory");
        for (std::uint32_t i = 0; i < tables; ++i) {
            const std::size_t rec = static_cast<std::size_t>(off) + 12 + 16u * i;
            const std::uint64_t o = u32(rec + 8), len = u32(rec + 12);
            if (o + len > n)
                truncated("table '" + tag_string(u32(rec)) + "' (bytes " + std::to_string(o) + ".." +
                          std::to_string(o + len) + ")");
        }
    };
    const std::uint32_t tag = u32(0);
    if (tag == 0x74746366u) {  // 'ttcf'
        const std::uint32_t fonts = u32(8);
        if (fonts == 0) font_error(source, "font collection with no fonts");
        if (12 + 4ull * fonts > n) truncated("the collection header");
        for (std::uint32_t i = 0; i < fonts; ++i) check_dir(u32(12 + 4u * i));
    } else if (tag == 0x00010000u || tag == 0x4f54544fu /*OTTO*/ || tag == 0x74727565u /*true*/ ||
               tag == 0x74797031u /*typ1*/) {
        check_dir(0);
    }
}

std::vector<std::uint8_t> read_font_file(const std::string& path) {
    std::error_code ec;
    const auto st = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(st)) throw Error(ErrorKind::Io, "cannot read font '" + path + "': no such file");
    if (std::filesystem::is_directory(st))
        throw Error(ErrorKind::Io, "cannot read font '" + path + "': it is a directory");
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw Error(ErrorKind::Io, "cannot read font '" + path + "': " + std::strerror(errno));
    // The buffer is reserved at the file's size, so appending never reallocates (nor zero-fills).
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    const std::uint64_t max_bytes = current_limits().font_file_bytes;
    if (!ec && size > max_bytes) {
        std::fclose(f);
        throw Error(ErrorKind::Limit, "font '" + path + "' is larger than " + std::to_string(max_bytes) + " bytes");
    }
    std::vector<std::uint8_t> bytes;
    if (!ec) bytes.reserve(static_cast<std::size_t>(size));
    std::uint8_t buf[65536];
    std::size_t got;
    while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) {
        bytes.insert(bytes.end(), buf, buf + got);
        if (bytes.size() > max_bytes) {
            std::fclose(f);
            throw Error(ErrorKind::Limit, "font '" + path + "' is larger than " + std::to_string(max_bytes) + " bytes");
        }
    }
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) throw Error(ErrorKind::Io, "cannot read font '" + path + "': read error");
    return bytes;
}

// A regular font file mapped read-only: FreeType and HarfBuzz then touch only the pages of the
// tables they read (a few of a 740 KB font for one line of text), instead of the whole file being
// copied into memory first. Returns null when the file cannot be mapped (not a regular file,
// empty, over the size limit: read_font_file reports those). Like FreeType's own FT_New_Face, which
// maps files too, this assumes the file is not truncated while the Font lives.
std::shared_ptr<const std::uint8_t> map_font_file(const std::string& path, std::size_t& size) {
    // Only a regular file is opened here: opening a FIFO would block for a writer, and closing it
    // again would cut that writer off before read_font_file reads it.
    struct stat path_st {};
    if (::stat(path.c_str(), &path_st) != 0 || !S_ISREG(path_st.st_mode)) return nullptr;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return nullptr;
    struct stat st {};
    void* addr = MAP_FAILED;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 &&
        static_cast<std::uint64_t>(st.st_size) <= current_limits().font_file_bytes) {
        size = static_cast<std::size_t>(st.st_size);
        addr = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    }
    ::close(fd);
    if (addr == MAP_FAILED) return nullptr;
    const std::size_t length = size;
    return std::shared_ptr<const std::uint8_t>(static_cast<const std::uint8_t*>(addr), [length](const std::uint8_t* p) {
        ::munmap(const_cast<std::uint8_t*>(p), length);
    });
}

// UTF-16BE (Windows name records) or Mac Roman / ASCII (Mac records) to UTF-8.
std::string name_to_utf8(const FT_SfntName& n) {
    std::string out;
    auto put = [&](std::uint32_t c) {
        if (c < 0x80) {
            out += static_cast<char>(c);
        } else if (c < 0x800) {
            out += static_cast<char>(0xc0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3f));
        } else if (c < 0x10000) {
            out += static_cast<char>(0xe0 | (c >> 12));
            out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
            out += static_cast<char>(0x80 | (c & 0x3f));
        } else {
            out += static_cast<char>(0xf0 | (c >> 18));
            out += static_cast<char>(0x80 | ((c >> 12) & 0x3f));
            out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
            out += static_cast<char>(0x80 | (c & 0x3f));
        }
    };
    if (n.platform_id == TT_PLATFORM_MICROSOFT || n.platform_id == TT_PLATFORM_APPLE_UNICODE) {
        for (FT_UInt i = 0; i + 1 < n.string_len; i += 2) {
            std::uint32_t c = static_cast<std::uint32_t>(n.string[i] << 8 | n.string[i + 1]);
            if (c >= 0xd800 && c < 0xdc00 && i + 3 < n.string_len) {
                const std::uint32_t lo = static_cast<std::uint32_t>(n.string[i + 2] << 8 | n.string[i + 3]);
                if (lo >= 0xdc00 && lo < 0xe000) {
                    c = 0x10000 + ((c - 0xd800) << 10) + (lo - 0xdc00);
                    i += 2;
                }
            }
            put(c);
        }
    } else {
        for (FT_UInt i = 0; i < n.string_len; ++i) put(n.string[i] < 0x80 ? n.string[i] : '?');
    }
    return out;
}

// The string with name id `id`, preferring Windows English, then any Windows, then Mac.
std::string sfnt_name(FT_Face face, FT_UInt id) {
    const FT_UInt count = FT_Get_Sfnt_Name_Count(face);
    int best_rank = -1;
    std::string best;
    for (FT_UInt i = 0; i < count; ++i) {
        FT_SfntName n;
        if (FT_Get_Sfnt_Name(face, i, &n) || n.name_id != id) continue;
        int rank = 0;
        if (n.platform_id == TT_PLATFORM_MICROSOFT)
            rank = n.language_id == 0x409 ? 3 : 2;
        else if (n.platform_id == TT_PLATFORM_MACINTOSH)
            rank = 1;
        if (rank > best_rank) {
            best_rank = rank;
            best = name_to_utf8(n);
        }
    }
    return best;
}

std::uint64_t hash_coords(const std::vector<double>& coords) {
    std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a over the 16.16 values
    for (double c : coords) {
        const auto v = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::lround(c * 65536.0)));
        for (int i = 0; i < 8; ++i) {
            h ^= (v >> (8 * i)) & 0xff;
            h *= 0x100000001b3ull;
        }
    }
    return h == 0 ? 1 : h;
}

struct DecomposeState {
    Path* path;
    bool open = false;
};

Point ft_point(const FT_Vector* v) {
    return {static_cast<double>(v->x) / kUnits26_6, static_cast<double>(v->y) / kUnits26_6};
}

int cb_move(const FT_Vector* to, void* user) {
    auto* s = static_cast<DecomposeState*>(user);
    if (s->open) s->path->close();
    s->path->move_to(ft_point(to));
    s->open = true;
    return 0;
}
int cb_line(const FT_Vector* to, void* user) {
    static_cast<DecomposeState*>(user)->path->line_to(ft_point(to));
    return 0;
}
int cb_conic(const FT_Vector* c, const FT_Vector* to, void* user) {
    static_cast<DecomposeState*>(user)->path->quad_to(ft_point(c), ft_point(to));
    return 0;
}
int cb_cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    static_cast<DecomposeState*>(user)->path->cubic_to(ft_point(c1), ft_point(c2), ft_point(to));
    return 0;
}

}  // namespace

void check_font_size(double size_px) {
    if (!std::isfinite(size_px) || size_px <= 0) {
        std::ostringstream o;
        o << "font size must be a positive number of pixels, got " << size_px;
        throw Error(ErrorKind::InvalidArgument, o.str());
    }
    if (size_px > limits::kMaxFontSize) {
        std::ostringstream o;
        o << "font size " << size_px << " px exceeds the limit of " << limits::kMaxFontSize << " px";
        throw Error(ErrorKind::Limit, o.str());
    }
}

Variation parse_variation(std::string_view text) {
    const auto eq = text.find('=');
    auto bad = [&](const std::string& why) -> Error {
        return Error(ErrorKind::Parse, "invalid variation '" + std::string(text) + "': " + why);
    };
    if (eq == std::string_view::npos) throw bad("expected TAG=VALUE, e.g. wght=700");
    std::string tag(text.substr(0, eq));
    if (tag.empty() || tag.size() > 4) throw bad("the axis tag must have 1 to 4 characters");
    for (char c : tag)
        if (c < 0x20 || c > 0x7e) throw bad("the axis tag must be printable ASCII");
    tag.resize(4, ' ');
    const std::string num(text.substr(eq + 1));
    if (num.empty()) throw bad("missing value after '='");
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(num.c_str(), &end);
    if (end != num.c_str() + num.size() || !std::isfinite(v) || errno == ERANGE)
        throw bad("the value must be a finite number");
    return {tag, v};
}

void set_chain_variations(std::span<Font* const> fonts, std::span<const Variation> settings) {
    auto has_axis = [](const Font& f, const Variation& v) {
        return std::any_of(f.axes().begin(), f.axes().end(), [&](const VariationAxis& a) { return a.tag == v.tag; });
    };
    for (const Variation& v : settings) {
        if (std::any_of(fonts.begin(), fonts.end(), [&](const Font* f) { return has_axis(*f, v); })) continue;
        std::string axes;
        for (const Font* f : fonts)
            for (const VariationAxis& a : f->axes()) axes += (axes.empty() ? "" : ", ") + a.tag;
        std::string tag = v.tag;
        while (!tag.empty() && tag.back() == ' ') tag.pop_back();
        throw Error(ErrorKind::Font, "unknown variation axis '" + tag + "': " +
                                         (axes.empty() ? std::string("no font given is a variable font")
                                                       : "the fonts' axes are " + axes));
    }
    for (Font* f : fonts) {
        std::vector<Variation> mine;
        for (const Variation& v : settings)
            for (const VariationAxis& a : f->axes())
                if (a.tag == v.tag) mine.push_back(v);
        if (!mine.empty()) f->set_variations(mine);
    }
}

Font::Impl::~Impl() {
    if (hb) hb_font_destroy(hb);
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
}

void Font::Impl::load_glyph(std::uint32_t glyph) const {
    if (glyph >= static_cast<std::uint32_t>(face->num_glyphs))
        font_error(source, "glyph id " + std::to_string(glyph) + " out of range (the font has " +
                               std::to_string(face->num_glyphs) + " glyphs)");
    const FT_Error err = FT_Load_Glyph(face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP);
    if (err) font_error(source, "cannot load glyph " + std::to_string(glyph) + ": " + ft_error_text(err));
    if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
        font_error(source, "glyph " + std::to_string(glyph) + " has no outline");
}

std::uint64_t Font::Impl::next_serial() {
    static std::atomic<std::uint64_t> counter{0};
    return counter.fetch_add(1, std::memory_order_relaxed);
}

void Font::Impl::variations_changed() {
    if (hb && !bitmap_only) hb_ft_font_changed(hb);
    auto pos = [&](hb_ot_metrics_tag_t tag) {
        hb_position_t p = 0;
        hb_ot_metrics_get_position_with_fallback(hb, tag, &p);
        return static_cast<double>(p) / kUnits26_6;
    };
    metrics.units_per_em = face->units_per_EM;
    metrics.ascender = pos(HB_OT_METRICS_TAG_HORIZONTAL_ASCENDER);
    metrics.descender = pos(HB_OT_METRICS_TAG_HORIZONTAL_DESCENDER);
    metrics.line_gap = pos(HB_OT_METRICS_TAG_HORIZONTAL_LINE_GAP);
    metrics.underline_position = pos(HB_OT_METRICS_TAG_UNDERLINE_OFFSET);
    metrics.underline_thickness = pos(HB_OT_METRICS_TAG_UNDERLINE_SIZE);
    metrics.strikeout_position = pos(HB_OT_METRICS_TAG_STRIKEOUT_OFFSET);
    metrics.strikeout_thickness = pos(HB_OT_METRICS_TAG_STRIKEOUT_SIZE);
    metrics.x_height = pos(HB_OT_METRICS_TAG_X_HEIGHT);
    metrics.cap_height = pos(HB_OT_METRICS_TAG_CAP_HEIGHT);
    metrics.subscript_offset = pos(HB_OT_METRICS_TAG_SUBSCRIPT_EM_Y_OFFSET);
    metrics.superscript_offset = pos(HB_OT_METRICS_TAG_SUPERSCRIPT_EM_Y_OFFSET);
    if (metrics.ascender <= metrics.descender) {  // broken tables: fall back to the em box
        metrics.ascender = 0.8 * face->units_per_EM;
        metrics.descender = -0.2 * face->units_per_EM;
    }
    var_key = axes.empty() ? 0 : hash_coords(coords);
}

Font::Font(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;
Font::~Font() = default;

Font Font::load(const std::string& path, int face_index) {
    std::size_t size = 0;
    if (auto mapped = map_font_file(path, size)) {
        check_face_index(face_index, path);
        check_sfnt_directory(mapped.get(), size, path);
        return from_shared_bytes(std::move(mapped), size, face_index, path);
    }
    return from_memory(read_font_file(path), face_index, path);
}

Font Font::from_memory(std::vector<std::uint8_t> bytes, int face_index, std::string name) {
    check_face_index(face_index, name);
    if (const std::uint64_t max_bytes = current_limits().font_file_bytes; bytes.size() > max_bytes)
        throw Error(ErrorKind::Limit, "font '" + name + "' is larger than " + std::to_string(max_bytes) + " bytes");
    check_sfnt_directory(bytes.data(), bytes.size(), name);
    auto owner = std::make_shared<const std::vector<std::uint8_t>>(std::move(bytes));
    const std::size_t size = owner->size();
    // An aliasing pointer: it points at the vector's bytes and keeps the vector alive.
    std::shared_ptr<const std::uint8_t> data(owner, owner->data());
    return from_shared_bytes(std::move(data), size, face_index, std::move(name));
}

// A Font over bytes already checked (load, from_memory), shared with the Fonts cloned from it.
Font Font::from_shared_bytes(std::shared_ptr<const std::uint8_t> bytes, std::size_t size, int face_index,
                             std::string name) {
    auto impl = std::make_unique<Impl>();
    impl->source = std::move(name);
    impl->face_index = face_index;
    impl->bytes = std::move(bytes);
    impl->size = size;
    if (FT_Error err = FT_Init_FreeType(&impl->library)) {
        impl->library = nullptr;
        font_error(impl->source, "cannot start FreeType: " + ft_error_text(err));
    }
    const auto* data = impl->bytes.get();
    const auto ft_size = static_cast<FT_Long>(impl->size);
    FT_Error err = FT_New_Memory_Face(impl->library, data, ft_size, face_index, &impl->face);
    if (err) {
        impl->face = nullptr;
        FT_Face probe = nullptr;
        if (face_index > 0 && FT_New_Memory_Face(impl->library, data, ft_size, -1, &probe) == 0) {
            const long n = probe->num_faces;
            FT_Done_Face(probe);
            if (face_index >= n)
                font_error(impl->source, "face index " + std::to_string(face_index) + " out of range (the file has " +
                                             std::to_string(n) + (n == 1 ? " face)" : " faces)"));
        }
        if (err == FT_Err_Unknown_File_Format)
            font_error(impl->source, "not a font file (FreeType does not recognise its format)");
        font_error(impl->source, "cannot open the font: " + ft_error_text(err));
    }
    FT_Face face = impl->face;
    impl->face_count = static_cast<int>(face->num_faces);
    impl->has_color_bitmaps = FT_HAS_COLOR(face) && FT_HAS_FIXED_SIZES(face);
    impl->bitmap_only = !FT_IS_SCALABLE(face);
    if (impl->bitmap_only && !impl->has_color_bitmaps)
        font_error(impl->source, "the font has no scalable outlines (bitmap-only)");
    if (impl->bitmap_only) {
        // FreeType leaves units_per_EM at 0 for a face without outlines; the head table has it, and
        // the metrics tables (hmtx, hhea) the layout reads are in those units.
        const auto* head = static_cast<const TT_Header*>(FT_Get_Sfnt_Table(face, FT_SFNT_HEAD));
        face->units_per_EM = head ? head->Units_Per_EM : 0;
    }
    if (face->units_per_EM < 16 || face->units_per_EM > 16384)
        font_error(impl->source, "unusable units per em: " + std::to_string(face->units_per_EM));
    FT_ULong colr_length = 0;
    impl->has_colr = FT_HAS_COLOR(face) &&
                     FT_Load_Sfnt_Table(face, FT_MAKE_TAG('C', 'O', 'L', 'R'), 0, nullptr, &colr_length) == 0 &&
                     colr_length > 0;
    FT_ULong svg_length = 0;
    impl->has_svg =
        FT_Load_Sfnt_Table(face, FT_MAKE_TAG('S', 'V', 'G', ' '), 0, nullptr, &svg_length) == 0 && svg_length > 0;
    if (impl->bitmap_only) {
        // Colour bitmaps only: the largest strike (glyphs are scaled from it when drawn).
        FT_Int largest = 0;
        for (FT_Int i = 1; i < face->num_fixed_sizes; ++i)
            if (face->available_sizes[i].y_ppem > face->available_sizes[largest].y_ppem) largest = i;
        if ((err = FT_Select_Size(face, largest)))
            font_error(impl->source, "cannot select a bitmap strike: " + ft_error_text(err));
    } else {
        // One size for everything: 1 px per font unit, so 26.6 values are 1/64 font units.
        const FT_F26Dot6 em = static_cast<FT_F26Dot6>(face->units_per_EM) * 64;
        if ((err = FT_Set_Char_Size(face, em, em, 72, 72)))
            font_error(impl->source, "cannot size the font: " + ft_error_text(err));
    }

    const char* fmt = FT_Get_Font_Format(face);
    const std::string format = fmt ? fmt : "";
    if (format == "TrueType")
        impl->format = OutlineFormat::TrueType;
    else if (format == "CFF")
        impl->format = OutlineFormat::CFF;
    else if (format == "CFF2")
        impl->format = OutlineFormat::CFF2;  // FreeType reports "CFF" for CFF2 in some versions
    else
        impl->format = OutlineFormat::Other;
    FT_ULong cff2_length = 0;
    if (impl->format == OutlineFormat::CFF &&
        FT_Load_Sfnt_Table(face, FT_MAKE_TAG('C', 'F', 'F', '2'), 0, nullptr, &cff2_length) == 0 && cff2_length > 0)
        impl->format = OutlineFormat::CFF2;

    if (FT_HAS_MULTIPLE_MASTERS(face)) {
        FT_MM_Var* mm = nullptr;
        if (FT_Get_MM_Var(face, &mm) == 0 && mm) {
            for (FT_UInt i = 0; i < mm->num_axis; ++i) {
                const FT_Var_Axis& a = mm->axis[i];
                FT_UInt flags = 0;
                FT_Get_Var_Axis_Flags(mm, i, &flags);
                impl->axes.push_back({tag_string(static_cast<std::uint32_t>(a.tag)), a.name ? a.name : "",
                                      a.minimum / 65536.0, a.def / 65536.0, a.maximum / 65536.0,
                                      (flags & FT_VAR_AXIS_FLAG_HIDDEN) != 0});
                impl->coords.push_back(a.def / 65536.0);
            }
            for (FT_UInt i = 0; i < mm->num_namedstyles; ++i) {
                NamedInstance ni;
                ni.name = sfnt_name(face, mm->namedstyle[i].strid);
                for (FT_UInt k = 0; k < mm->num_axis; ++k)
                    ni.coordinates.push_back(mm->namedstyle[i].coords[k] / 65536.0);
                impl->instances.push_back(std::move(ni));
            }
            FT_Done_MM_Var(impl->library, mm);
        }
    }

    if (impl->bitmap_only) {
        // FreeType has no outline advances for a bitmap face: HarfBuzz reads the font's own tables.
        hb_blob_t* blob = hb_blob_create(reinterpret_cast<const char*>(data), static_cast<unsigned>(impl->size),
                                         HB_MEMORY_MODE_READONLY, nullptr, nullptr);
        hb_face_t* hface = hb_face_create(blob, static_cast<unsigned>(face_index));
        hb_blob_destroy(blob);
        impl->hb = hb_font_create(hface);
        hb_face_destroy(hface);
        const int scale = static_cast<int>(face->units_per_EM) * 64;
        hb_font_set_scale(impl->hb, scale, scale);
    } else {
        impl->hb = hb_ft_font_create_referenced(face);
        if (!impl->hb) font_error(impl->source, "HarfBuzz cannot use the face");
        hb_ft_font_set_load_flags(impl->hb, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP);
    }
    impl->variations_changed();
    return Font(std::move(impl));
}

Font Font::clone() const {
    Font f = from_shared_bytes(impl_->bytes, impl_->size, impl_->face_index, impl_->source);
    if (is_variable()) {
        std::vector<Variation> v;
        for (std::size_t i = 0; i < impl_->axes.size(); ++i) v.push_back({impl_->axes[i].tag, impl_->coords[i]});
        f.set_variations(v);
    }
    return f;
}

const std::string& Font::source() const { return impl_->source; }
int Font::face_index() const { return impl_->face_index; }
int Font::face_count() const { return impl_->face_count; }
std::string Font::family_name() const { return impl_->face->family_name ? impl_->face->family_name : ""; }
std::string Font::style_name() const { return impl_->face->style_name ? impl_->face->style_name : ""; }
OutlineFormat Font::outline_format() const { return impl_->format; }
int Font::units_per_em() const { return impl_->face->units_per_EM; }
std::uint32_t Font::glyph_count() const { return static_cast<std::uint32_t>(impl_->face->num_glyphs); }
const FontMetrics& Font::metrics() const { return impl_->metrics; }

std::uint32_t Font::glyph_index(char32_t codepoint) const {
    return FT_Get_Char_Index(impl_->face, static_cast<FT_ULong>(codepoint));
}

Path Font::glyph_path(std::uint32_t glyph) const {
    Path p;
    glyph_path(glyph, p);
    return p;
}

void Font::glyph_path(std::uint32_t glyph, Path& out) const {
    out.clear();
    if (impl_->bitmap_only && glyph < glyph_count()) return;  // colour bitmaps have no outline
    impl_->load_glyph(glyph);
    static constexpr FT_Outline_Funcs funcs = {cb_move, cb_line, cb_conic, cb_cubic, 0, 0};
    DecomposeState st{&out};
    const FT_Error err = FT_Outline_Decompose(&impl_->face->glyph->outline, &funcs, &st);
    if (err) {
        out.clear();
        font_error(impl_->source, "cannot decompose glyph " + std::to_string(glyph) + ": " + ft_error_text(err));
    }
    if (st.open) out.close();
}

GlyphMetrics Font::glyph_metrics(std::uint32_t glyph) const {
    if (impl_->bitmap_only && glyph < glyph_count()) {
        GlyphMetrics m;
        m.advance = hb_font_get_glyph_h_advance(impl_->hb, glyph) / kUnits26_6;
        m.bounds = text_detail::color_glyph_bounds(*this, glyph);
        m.left_bearing = m.bounds.empty() ? 0 : m.bounds.x0;
        m.right_bearing = m.advance - (m.bounds.empty() ? 0 : m.bounds.x1);
        return m;
    }
    impl_->load_glyph(glyph);
    const FT_GlyphSlot slot = impl_->face->glyph;
    GlyphMetrics m;
    m.advance = static_cast<double>(slot->linearHoriAdvance) / 65536.0;
    if (slot->outline.n_points > 0) {
        FT_BBox box;
        FT_Outline_Get_BBox(&slot->outline, &box);
        m.bounds = {box.xMin / kUnits26_6, box.yMin / kUnits26_6, box.xMax / kUnits26_6, box.yMax / kUnits26_6};
        m.left_bearing = m.bounds.x0;
        m.right_bearing = m.advance - m.bounds.x1;
    } else {
        m.right_bearing = m.advance;
    }
    return m;
}

Affine Font::glyph_transform(double size_px, Point origin) const {
    check_font_size(size_px);
    const double s = size_px / impl_->face->units_per_EM;
    return {s, 0, 0, -s, origin.x, origin.y};
}

bool Font::is_variable() const { return !impl_->axes.empty(); }
const std::vector<VariationAxis>& Font::axes() const { return impl_->axes; }
const std::vector<NamedInstance>& Font::named_instances() const { return impl_->instances; }
std::vector<double> Font::variation_coordinates() const { return impl_->coords; }
std::uint64_t Font::variation_key() const { return impl_->var_key; }

void Font::set_variations(std::span<const Variation> settings) {
    auto axis_list = [&] {
        std::string s;
        for (const auto& a : impl_->axes) s += (s.empty() ? "" : ", ") + a.tag;
        return s;
    };
    if (!settings.empty() && impl_->axes.empty())
        font_error(impl_->source, "cannot set variation '" + settings.front().tag +
                                      "': the font is not a variable font (it has no axes)");
    std::vector<double> coords;
    for (const auto& a : impl_->axes) coords.push_back(a.default_value);
    for (const Variation& v : settings) {
        std::string tag = v.tag;
        if (tag.size() < 4) tag.resize(4, ' ');
        std::size_t i = 0;
        while (i < impl_->axes.size() && impl_->axes[i].tag != tag) ++i;
        std::string shown = tag;
        while (!shown.empty() && shown.back() == ' ') shown.pop_back();
        if (i == impl_->axes.size())
            font_error(impl_->source, "unknown variation axis '" + shown + "' (the font's axes: " + axis_list() + ")");
        if (!std::isfinite(v.value))
            throw Error(ErrorKind::InvalidArgument, "variation '" + shown + "' must be a finite number");
        coords[i] = std::clamp(v.value, impl_->axes[i].minimum, impl_->axes[i].maximum);
    }
    if (impl_->axes.empty()) return;
    std::vector<FT_Fixed> fixed;
    for (double c : coords) fixed.push_back(static_cast<FT_Fixed>(std::lround(c * 65536.0)));
    if (FT_Error err = FT_Set_Var_Design_Coordinates(impl_->face, static_cast<FT_UInt>(fixed.size()), fixed.data()))
        font_error(impl_->source, "cannot set variations: " + ft_error_text(err));
    impl_->coords = std::move(coords);
    impl_->variations_changed();
}

void Font::set_named_instance(std::size_t index) {
    if (index >= impl_->instances.size())
        font_error(impl_->source, "named instance " + std::to_string(index) + " out of range (the font has " +
                                      std::to_string(impl_->instances.size()) + ")");
    std::vector<Variation> v;
    for (std::size_t i = 0; i < impl_->axes.size(); ++i)
        v.push_back({impl_->axes[i].tag, impl_->instances[index].coordinates[i]});
    set_variations(v);
}

void Font::set_named_instance(std::string_view name) {
    auto lower = [](std::string_view s) {
        std::string r(s);
        for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return r;
    };
    const std::string want = lower(name);
    std::string names;
    for (std::size_t i = 0; i < impl_->instances.size(); ++i) {
        if (lower(impl_->instances[i].name) == want) return set_named_instance(i);
        names += (names.empty() ? "" : ", ") + impl_->instances[i].name;
    }
    font_error(impl_->source,
               "no named instance '" + std::string(name) + "'" +
                   (names.empty() ? std::string(" (the font has none)") : " (the font has: " + names + ")"));
}

void Font::reset_variations() { set_variations({}); }

}  // namespace casteljau
