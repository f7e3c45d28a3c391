// Text stage, system font fallback: the answers kept across processes, their file format and the
// stamp that says whether they still hold (src/text/fallback_cache.hpp).
//
// The file is text, one record a line, fields separated by one space:
//   casteljau fallback cache 1
//   s NAME VALUE          stamp entries, then
//   f INDEX FILE          faces (face index in decimal, the font file), then
//   a FACE KEY            answers: the face's number among the f lines or -1, the key's code
//                         points in lower-case hexadecimal joined by commas, in key order.
// Names, values and files escape the bytes 0x00-0x20, 0x7F and '%' as %XX (upper-case hex).
#include "text/fallback_cache.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"

namespace casteljau::text_detail {

namespace {

constexpr std::string_view kHeader = "casteljau fallback cache 1";
constexpr const char* kFileName = "fallback-1.cache";

// The environment variables that decide fontconfig's configuration and default language.
constexpr const char* kEnvironment[] = {
    "FONTCONFIG_FILE", "FONTCONFIG_PATH", "FONTCONFIG_SYSROOT", "FC_LANG", "LC_ALL", "LC_CTYPE", "LANG", "HOME",
    "XDG_CONFIG_HOME", "XDG_DATA_HOME"};

bool needs_escape(unsigned char c) { return c <= 0x20 || c == 0x7f || c == '%'; }

void append_escaped(std::string& out, std::string_view s) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (needs_escape(c)) {
            out += '%';
            out += kHex[c >> 4];
            out += kHex[c & 15];
        } else {
            out += ch;
        }
    }
}

int hex_digit(char c, bool upper) {
    if (c >= '0' && c <= '9') return c - '0';
    if (upper && c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (!upper && c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

// The bytes an escaped field stands for; nullopt unless it is exactly as append_escaped writes it.
std::optional<std::string> unescape(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c != '%') {
            if (needs_escape(c)) return std::nullopt;
            out += s[i];
            continue;
        }
        if (s.size() - i < 3) return std::nullopt;
        const int hi = hex_digit(s[i + 1], true), lo = hex_digit(s[i + 2], true);
        if (hi < 0 || lo < 0) return std::nullopt;
        const auto decoded = static_cast<unsigned char>(hi * 16 + lo);
        if (!needs_escape(decoded)) return std::nullopt;
        out += static_cast<char>(decoded);
        i += 2;
    }
    return out;
}

// A decimal number from 0 to `max` with no sign and no leading zero.
std::optional<long long> parse_decimal(std::string_view s, long long max) {
    if (s.empty() || s.size() > 12 || (s.size() > 1 && s[0] == '0')) return std::nullopt;
    long long v = 0;
    for (const char c : s) {
        if (c < '0' || c > '9') return std::nullopt;
        v = v * 10 + (c - '0');
    }
    if (v > max) return std::nullopt;
    return v;
}

// A key: lower-case hexadecimal code points (no leading zero, at most 0x10FFFF) joined by commas.
std::optional<std::u32string> parse_key(std::string_view s) {
    std::u32string key;
    std::size_t at = 0;
    while (true) {
        const std::size_t comma = std::min(s.find(',', at), s.size());
        const std::string_view digits = s.substr(at, comma - at);
        if (digits.empty() || digits.size() > 6 || (digits.size() > 1 && digits[0] == '0')) return std::nullopt;
        char32_t v = 0;
        for (const char c : digits) {
            const int d = hex_digit(c, false);
            if (d < 0) return std::nullopt;
            v = v * 16 + static_cast<char32_t>(d);
        }
        if (v > 0x10FFFF || key.size() >= kMaxCacheKeyLength) return std::nullopt;
        key.push_back(v);
        if (comma == s.size()) return key;
        at = comma + 1;
    }
}

void append_key(std::string& out, const std::u32string& key) {
    static constexpr char kHex[] = "0123456789abcdef";
    for (std::size_t i = 0; i < key.size(); ++i) {
        if (i) out += ',';
        char buf[8];
        int n = 0;
        char32_t v = key[i];
        do {
            buf[n++] = kHex[v & 15];
            v >>= 4;
        } while (v);
        while (n) out += buf[--n];
    }
}

// Splits a line into exactly `n` fields at single spaces (the last field is the rest).
bool split(std::string_view line, std::size_t n, std::string_view* fields) {
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const std::size_t sp = line.find(' ');
        if (sp == std::string_view::npos) return false;
        fields[i] = line.substr(0, sp);
        line.remove_prefix(sp + 1);
    }
    fields[n - 1] = line;
    return true;
}

std::optional<std::string> environment_value(const char* name) {
    const char* v = std::getenv(name);
    if (!v) return std::nullopt;
    return std::string(v);
}

}  // namespace

std::optional<std::string> format_fallback_cache(const FallbackCacheData& data) {
    if (data.stamp.size() > kMaxCacheStamp || data.faces.size() > kMaxCacheFaces ||
        data.answers.size() > kMaxCacheAnswers)
        return std::nullopt;
    std::string out(kHeader);
    out += '\n';
    for (const auto& [name, value] : data.stamp) {
        out += "s ";
        append_escaped(out, name);
        out += ' ';
        append_escaped(out, value);
        out += '\n';
    }
    for (const auto& [file, index] : data.faces) {
        if (index < 0 || file.empty()) return std::nullopt;
        out += "f " + std::to_string(index) + ' ';
        append_escaped(out, file);
        out += '\n';
    }
    std::vector<const std::pair<const std::u32string, int>*> answers;
    answers.reserve(data.answers.size());
    for (const auto& a : data.answers) {
        if (a.first.empty() || a.first.size() > kMaxCacheKeyLength || a.second < -1 ||
            a.second >= static_cast<int>(data.faces.size()))
            return std::nullopt;
        if (std::any_of(a.first.begin(), a.first.end(), [](char32_t c) { return c > 0x10FFFF; })) return std::nullopt;
        answers.push_back(&a);
    }
    std::sort(answers.begin(), answers.end(), [](const auto* x, const auto* y) { return x->first < y->first; });
    for (const auto* a : answers) {
        out += "a " + std::to_string(a->second) + ' ';
        append_key(out, a->first);
        out += '\n';
    }
    return out;
}

std::optional<FallbackCacheData> parse_fallback_cache(std::string_view text) {
    if (text.size() > kMaxCacheBytes || text.empty() || text.back() != '\n') return std::nullopt;
    FallbackCacheData data;
    int section = 0;  // 0: header, 1: stamp, 2: faces, 3: answers
    std::u32string previous_key;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = text.find('\n', at);
        const std::string_view line = text.substr(at, end - at);
        at = end + 1;
        if (section == 0) {
            if (line != kHeader) return std::nullopt;
            section = 1;
            continue;
        }
        std::string_view f[3];
        if (!split(line, 3, f) || f[0].size() != 1) return std::nullopt;
        const int kind = f[0][0] == 's' ? 1 : f[0][0] == 'f' ? 2 : f[0][0] == 'a' ? 3 : 0;
        if (kind == 0 || kind < section) return std::nullopt;
        section = kind;
        if (kind == 1) {
            auto name = unescape(f[1]), value = unescape(f[2]);
            if (!name || !value || data.stamp.size() >= kMaxCacheStamp) return std::nullopt;
            data.stamp.emplace_back(std::move(*name), std::move(*value));
        } else if (kind == 2) {
            const auto index = parse_decimal(f[1], 0x7fffffff);
            auto file = unescape(f[2]);
            if (!index || !file || file->empty() || data.faces.size() >= kMaxCacheFaces) return std::nullopt;
            data.faces.emplace_back(std::move(*file), static_cast<int>(*index));
        } else {
            std::optional<long long> face;
            if (f[1] == "-1")
                face = -1;
            else
                face = parse_decimal(f[1], static_cast<long long>(data.faces.size()) - 1);
            auto key = parse_key(f[2]);
            // Keys strictly increasing: each once, in the order format_fallback_cache writes them.
            if (!face || !key || data.answers.size() >= kMaxCacheAnswers ||
                (!data.answers.empty() && !(previous_key < *key)))
                return std::nullopt;
            previous_key = *key;
            data.answers.emplace(std::move(*key), static_cast<int>(*face));
        }
    }
    if (section == 0) return std::nullopt;
    return data;
}

std::string current_stamp_value(const std::string& name) {
    if (name.rfind("env ", 0) == 0) {
        const auto v = environment_value(name.c_str() + 4);
        return v ? "=" + *v : "-";
    }
    if (name.rfind("path ", 0) == 0) {
        struct stat st;
        if (::stat(name.c_str() + 5, &st) != 0) return "-";
        return std::to_string(static_cast<long long>(st.st_mtim.tv_sec)) + "." +
               std::to_string(static_cast<long long>(st.st_mtim.tv_nsec)) + " " +
               std::to_string(static_cast<long long>(st.st_size));
    }
    return "?";  // an entry this version does not make: never current
}

std::vector<std::pair<std::string, std::string>> environment_stamp() {
    std::vector<std::pair<std::string, std::string>> stamp;
    for (const char* name : kEnvironment) {
        std::string key = std::string("env ") + name;
        std::string value = current_stamp_value(key);
        stamp.emplace_back(std::move(key), std::move(value));
    }
    return stamp;
}

std::vector<std::pair<std::string, std::string>> make_stamp(const std::vector<std::string>& paths) {
    std::vector<std::pair<std::string, std::string>> stamp = environment_stamp();
    std::set<std::string> seen;
    for (const std::string& p : paths) {
        if (p.empty() || !seen.insert(p).second) continue;
        std::string key = "path " + p;
        std::string value = current_stamp_value(key);
        stamp.emplace_back(std::move(key), std::move(value));
    }
    return stamp;
}

bool stamp_is_current(const std::vector<std::pair<std::string, std::string>>& stamp) {
    std::size_t environment = 0;
    for (const auto& [name, value] : stamp) {
        if (current_stamp_value(name) != value) return false;
        if (name.rfind("env ", 0) == 0) ++environment;
    }
    // Every variable must have been recorded: a file missing one says nothing about it.
    const std::vector<std::pair<std::string, std::string>> now = environment_stamp();
    return environment >= now.size() && std::all_of(now.begin(), now.end(), [&](const auto& e) {
               return std::find(stamp.begin(), stamp.end(), e) != stamp.end();
           });
}

std::string fallback_cache_path() {
    namespace fs = std::filesystem;
    if (const auto dir = environment_value("CASTELJAU_CACHE_DIR"))
        return dir->empty() ? std::string() : (fs::path(*dir) / kFileName).string();
    if (const auto xdg = environment_value("XDG_CACHE_HOME"); xdg && !xdg->empty() && (*xdg)[0] == '/')
        return (fs::path(*xdg) / "casteljau" / kFileName).string();
    if (const auto home = environment_value("HOME"); home && !home->empty() && (*home)[0] == '/')
        return (fs::path(*home) / ".cache" / "casteljau" / kFileName).string();
    return {};
}

std::optional<FallbackCacheData> load_fallback_cache(const std::string& path) {
    if (path.empty()) return std::nullopt;
    struct stat st;
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) ||
        static_cast<unsigned long long>(st.st_size) > kMaxCacheBytes)
        return std::nullopt;
    std::vector<std::uint8_t> bytes;
    try {
        bytes = read_file(path);
    } catch (const Error&) { return std::nullopt; }
    auto data = parse_fallback_cache(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    if (!data || !stamp_is_current(data->stamp)) return std::nullopt;
    return data;
}

bool store_fallback_cache(const std::string& path, const FallbackCacheData& data) {
    if (path.empty()) return false;
    const auto text = format_fallback_cache(data);
    if (!text) return false;
    try {
        std::error_code ec;
        std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
        if (ec) return false;
        write_file_atomic(path, std::span(reinterpret_cast<const std::uint8_t*>(text->data()), text->size()));
    } catch (const std::exception&) { return false; }
    return true;
}

}  // namespace casteljau::text_detail
