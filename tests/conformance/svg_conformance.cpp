// svg_conformance: renders every file of the whole resvg test suite
// (../shared/conformance/resvg-suite, 1,721 files listed in its manifest.tsv) at the suite's
// reference size, compares each with its reference PNG by rule B (primary) and rule A (secondary)
// of ../shared/conformance/resvg/README.md (tests/support/resvg_compare.hpp), prints pass counts per area
// and per feature folder, writes every failure as a diff picture (actual | reference | bad pixels)
// into the output folder, and fails when a count drops below the minimum recorded in
// CONFORMANCE.md's counts table.
//
// Usage: svg_conformance [--suite DIR] [--counts FILE] [--out DIR] [--threads N] [--stride N]
//                        [--only TEXT] [--update] [--no-images]
//   --stride N   render every N-th file only (the sanitizer build); the minimums are not checked
//   --only TEXT  render only files whose path contains TEXT; the minimums are not checked
//   --update     raise the recorded minimums in FILE to today's counts (never lowers one)
// Exit codes: 0 every count at or above its minimum, 1 a count dropped (or a file threw something
// other than a casteljau::Error), 2 bad usage, 77 the suite is absent (ctest reports a skip).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "resvg_compare.hpp"

namespace fs = std::filesystem;
using namespace casteljau;

namespace {

constexpr int kSkip = 77;
constexpr const char* kBegin = "<!-- conformance-counts:begin -->";
constexpr const char* kEnd = "<!-- conformance-counts:end -->";

struct Entry {
    std::string svg, png, area, feature;
};

struct Outcome {
    bool pass_a = false, pass_b = false;
    bool hard_failure = false;  // threw something other than a casteljau::Error
    std::string why;
    double seconds = 0;
};

struct Count {
    int b = 0, a = 0, total = 0;
};

std::vector<std::string> split(const std::string& line, char sep) {
    std::vector<std::string> out;
    std::stringstream ss(line);
    std::string f;
    while (std::getline(ss, f, sep)) out.push_back(f);
    return out;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// The counts table of CONFORMANCE.md: rows `| key | B min | A min | total |` between the markers.
std::map<std::string, Count> read_counts(const fs::path& file) {
    std::map<std::string, Count> out;
    std::ifstream in(file);
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line.find(kBegin) != std::string::npos) {
            inside = true;
            continue;
        }
        if (line.find(kEnd) != std::string::npos) break;
        if (!inside || line.empty() || line[0] != '|') continue;
        const auto cells = split(line, '|');
        if (cells.size() < 5) continue;
        try {
            Count c;
            c.b = std::stoi(trim(cells[2]));
            c.a = std::stoi(trim(cells[3]));
            c.total = std::stoi(trim(cells[4]));
            out[trim(cells[1])] = c;
        } catch (const std::exception&) {
            // header or separator row
        }
    }
    return out;
}

std::string table(const std::map<std::string, Count>& counts) {
    std::string t = std::string(kBegin) +
                    "\n| area or feature | rule B (min) | rule A (min) | files |\n| --- | ---: | ---: | ---: |\n";
    for (const auto& [k, c] : counts)
        t += "| " + k + " | " + std::to_string(c.b) + " | " + std::to_string(c.a) + " | " + std::to_string(c.total) +
             " |\n";
    return t + kEnd + "\n";
}

// Text uses the suite's own fonts only, with the generic families its README names, so that the
// results do not depend on the fonts installed. One database for the whole run.
SvgOptions suite_options(const fs::path& suite) {
    static std::mutex m;
    static std::shared_ptr<const FontDatabase> db;
    std::lock_guard<std::mutex> lock(m);
    if (!db) {
        FontDatabaseOptions fo;
        fo.font_dirs = {(suite / "fonts").string()};
        fo.system_fonts = false;
        db = std::make_shared<const FontDatabase>(fo);
    }
    SvgOptions o;
    o.font_database = db;
    o.system_fonts = false;
    o.font_family = "Noto Serif";
    o.sans_serif_family = "Noto Sans";
    o.serif_family = "Noto Serif";
    o.cursive_family = "Yellowtail";
    o.fantasy_family = "Sedgwick Ave Display";
    o.monospace_family = "Noto Mono";
    return o;
}

Outcome run_one(const fs::path& suite, const Entry& e, const fs::path& out_dir, bool images) {
    Outcome o;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        const Pixmap ref = read_png((suite / e.png).string());
        Pixmap actual;
        try {
            // Images may read the suite's resources/ folder (outside each test's own folder).
            SvgOptions so = suite_options(suite);
            so.resource_root = suite.string();
            const SvgDocument doc = SvgDocument::load((suite / e.svg).string(), so);
            actual = resvg_compare::render_reference_size(doc);
        } catch (const Error& err) { o.why = std::string("error: ") + err.what(); }
        if (actual.width() == 0) {
            // A rejected file passes when the reference shows nothing.
            bool empty = true;
            for (int y = 0; y < ref.height() && empty; ++y)
                for (int x = 0; x < ref.width() && empty; ++x) empty = ref.pixel(x, y).a == 0;
            o.pass_a = o.pass_b = empty;
        } else {
            const resvg_compare::Result r = resvg_compare::compare(actual, ref);
            o.pass_a = r.pass_a;
            o.pass_b = r.pass_b;
            if (!r.size_ok)
                o.why = "size " + std::to_string(actual.width()) + "x" + std::to_string(actual.height()) +
                        ", reference " + std::to_string(ref.width()) + "x" + std::to_string(ref.height());
            else if (!r.pass_b)
                o.why = std::to_string(r.bad_b) + " bad pixels (rule B), " + std::to_string(r.bad_a) + " (rule A)";
            if (!r.pass_b && images) {
                fs::path p = out_dir / e.svg;
                p.replace_extension(".png");
                fs::create_directories(p.parent_path());
                write_png(resvg_compare::diff_image(actual, ref), p.string());
            }
        }
    } catch (const std::exception& ex) {
        o.hard_failure = true;
        o.pass_a = o.pass_b = false;
        o.why = std::string("unexpected exception: ") + ex.what();
    }
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path suite = resvg_compare::shared_dir() / "conformance" / "resvg-suite";
    fs::path counts_file = fs::path(CASTELJAU_SOURCE_DIR) / "CONFORMANCE.md";
    fs::path out_dir = fs::path(CASTELJAU_BINARY_DIR) / "svg_conformance";
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    int stride = 1;
    std::string only;
    bool update = false, images = true;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::cerr << "svg_conformance: " << a << " needs a value\n";
                std::exit(2);
            }
            return argv[++i];
        };
        try {
            if (a == "--suite")
                suite = value();
            else if (a == "--counts")
                counts_file = value();
            else if (a == "--out")
                out_dir = value();
            else if (a == "--threads")
                threads = static_cast<unsigned>(std::max(1, std::stoi(value())));
            else if (a == "--stride")
                stride = std::max(1, std::stoi(value()));
            else if (a == "--only")
                only = value();
            else if (a == "--update")
                update = true;
            else if (a == "--no-images")
                images = false;
            else {
                std::cerr << "svg_conformance: unknown option " << a << "\n";
                return 2;
            }
        } catch (const std::exception&) {
            std::cerr << "svg_conformance: bad value for " << a << "\n";
            return 2;
        }
    }
    if (!fs::exists(suite / "manifest.tsv")) {
        std::cout << "SKIPPED: the resvg suite is not at " << suite.string()
                  << " (../shared absent; set CASTELJAU_SHARED_DIR or pass --suite)\n";
        return kSkip;
    }
    std::vector<Entry> entries;
    {
        std::ifstream manifest(suite / "manifest.tsv");
        std::string line;
        std::getline(manifest, line);  // header
        int index = 0;
        while (std::getline(manifest, line)) {
            const auto f = split(line, '\t');
            if (f.size() < 4) continue;
            if (index++ % stride != 0) continue;
            if (!only.empty() && f[0].find(only) == std::string::npos) continue;
            entries.push_back({f[0], f[1], f[2], f[2] + "/" + f[3]});
        }
    }
    const bool whole = stride == 1 && only.empty();
    std::error_code ec;
    fs::remove_all(out_dir, ec);
    fs::create_directories(out_dir);

    std::vector<Outcome> outcomes(entries.size());
    std::atomic<std::size_t> next{0};
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (std::size_t i = next++; i < entries.size(); i = next++)
                outcomes[i] = run_one(suite, entries[i], out_dir, images);
        });
    for (auto& th : pool) th.join();
    const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::map<std::string, Count> counts;
    int hard = 0;
    std::ofstream failures(out_dir / "failures.tsv");
    failures << "svg\tarea\tfeature\trule_a\twhy\n";
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const Entry& e = entries[i];
        const Outcome& o = outcomes[i];
        for (const std::string& key : {std::string("all"), e.area, e.feature}) {
            Count& c = counts[key];
            c.total++;
            c.b += o.pass_b;
            c.a += o.pass_a;
        }
        hard += o.hard_failure;
        if (!o.pass_b)
            failures << e.svg << '\t' << e.area << '\t' << e.feature << '\t' << (o.pass_a ? "pass" : "fail") << '\t'
                     << o.why << '\n';
        if (o.hard_failure) std::cout << "HARD FAILURE " << e.svg << ": " << o.why << "\n";
    }
    std::vector<std::size_t> order(entries.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return outcomes[a].seconds > outcomes[b].seconds; });

    std::printf("resvg suite: %zu files in %.1f s on %u threads; failures and diff pictures in %s\n", entries.size(),
                total_s, threads, out_dir.string().c_str());
    std::printf("%-36s %9s %9s %6s\n", "area / feature", "rule B", "rule A", "files");
    for (const auto& [k, c] : counts)
        std::printf("%-36s %9d %9d %6d%s\n", k.c_str(), c.b, c.a, c.total,
                    k.find('/') == std::string::npos ? "   <- area" : "");
    std::printf("slowest:");
    for (std::size_t i = 0; i < std::min<std::size_t>(5, order.size()); ++i)
        std::printf(" %s (%.2f s)", entries[order[i]].svg.c_str(), outcomes[order[i]].seconds);
    std::printf("\n");

    if (!whole) {
        std::printf("subset run (--stride/--only): recorded minimums not checked\n");
        return hard ? 1 : 0;
    }
    const std::map<std::string, Count> recorded = read_counts(counts_file);
    int dropped = 0;
    for (const auto& [k, rec] : recorded) {
        const auto it = counts.find(k);
        const Count now = it == counts.end() ? Count{} : it->second;
        if (now.b < rec.b || now.a < rec.a) {
            std::printf("DROPPED %s: rule B %d (minimum %d), rule A %d (minimum %d)\n", k.c_str(), now.b, rec.b, now.a,
                        rec.a);
            ++dropped;
        }
    }
    if (recorded.empty()) std::printf("no counts table in %s: nothing checked\n", counts_file.string().c_str());
    if (update) {
        std::map<std::string, Count> merged = counts;
        for (auto& [k, c] : merged)
            if (const auto it = recorded.find(k); it != recorded.end()) {
                c.b = std::max(c.b, it->second.b);
                c.a = std::max(c.a, it->second.a);
            }
        std::ifstream in(counts_file);
        std::stringstream all;
        all << in.rdbuf();
        std::string text = all.str();
        const auto b = text.find(kBegin), e = text.find(kEnd);
        if (b == std::string::npos || e == std::string::npos) {
            std::cerr << "svg_conformance: no counts markers in " << counts_file.string() << "\n";
            return 2;
        }
        std::size_t rest = e + std::string(kEnd).size();
        if (rest < text.size() && text[rest] == '\n') ++rest;
        text = text.substr(0, b) + table(merged) + text.substr(rest);
        std::ofstream(counts_file) << text;
        std::printf("updated %s\n", counts_file.string().c_str());
    }
    return dropped || hard ? 1 : 0;
}
