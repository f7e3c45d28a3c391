// casteljau/font_database.hpp: finding fonts by family name, weight, style and stretch (CSS font
// matching), and per-character fallback. A FontDatabase lists the faces of font folders and, when
// asked, of the system (through fontconfig); it reads each font file at most once and hands out
// independent Fonts (font.hpp) that share the file's bytes.
//
// Matching follows CSS Fonts 4 section 5.2 for one family: the faces of that family (any of its
// names, case-insensitive) are narrowed by font-stretch, then font-style (italic prefers italic,
// then oblique, then normal; oblique prefers oblique, then italic), then font-weight (400 tries
// 400..500 first, then lighter, then heavier; below 400 lighter first; above 500 heavier first).
// A variable face covers the weights and widths of its axes.
//
// Coordinates: none (fonts are in font units, see font.hpp).
// Thread-safety: a FontDatabase is immutable after construction except for its cache of loaded
// files, which a mutex guards: one database may serve many threads at once. The Fonts it returns
// are independent objects (one thread each, as font.hpp says).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/font.hpp"

namespace casteljau {

enum class FontSlant { Normal, Italic, Oblique };

// One face of a font file.
struct FontFaceInfo {
    std::string path;
    int index = 0;                           // face index in a collection
    std::vector<std::string> families;       // every family name the file gives (typographic first)
    int weight = 400;                        // CSS weight 1..1000 (the default instance for variable fonts)
    int min_weight = 400, max_weight = 400;  // range covered (variable fonts: the wght axis)
    FontSlant slant = FontSlant::Normal;
    double stretch = 100;  // CSS percentage: 50 (ultra-condensed) .. 200 (ultra-expanded)
    bool variable = false;
    bool system = false;  // found through fontconfig (FontDatabaseOptions::system_fonts), not given
};

struct FontDatabaseOptions {
    std::vector<std::string> font_dirs;   // folders scanned (recursively) for .ttf .otf .ttc .otc
    std::vector<std::string> font_files;  // single font files
    bool system_fonts = true;             // add every face fontconfig knows
};

// Throws Error(Io), as FontDatabase's constructor does, when a folder or file of `options` does
// not exist; reads no font. For callers that build the database only once text needs it.
void check_font_sources(const FontDatabaseOptions& options);

class FontDatabase {
public:
    // Scans the folders, files and (optionally) the system fonts. A folder or file that does not
    // exist throws Error(Io); files in a folder that are not fonts are skipped.
    explicit FontDatabase(const FontDatabaseOptions& options);
    ~FontDatabase();
    FontDatabase(const FontDatabase&) = delete;
    FontDatabase& operator=(const FontDatabase&) = delete;

    const std::vector<FontFaceInfo>& faces() const;

    // The best face of `family` for the weight, slant and stretch (see above); nothing when no face
    // has that family name.
    std::optional<std::size_t> match(std::string_view family, int weight = 400, FontSlant slant = FontSlant::Normal,
                                     double stretch = 100) const;
    // Whether face `face` maps code point `c` to a glyph.
    bool covers(std::size_t face, char32_t c) const;
    // The first face (in database order, best matching weight/slant/stretch among the faces that
    // cover `c`) that has `c`; nothing when no face has it. `system_faces` false: only among the
    // faces of the folders and files given (for callers that ask fontconfig's fallback next).
    std::optional<std::size_t> fallback(char32_t c, int weight = 400, FontSlant slant = FontSlant::Normal,
                                        double stretch = 100, bool system_faces = true) const;

    // An independent Font for face `face`; the file is read once per database and its bytes
    // shared. Throws Error(Io) or Error(Font) when the file cannot be read.
    Font open(std::size_t face) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace casteljau
