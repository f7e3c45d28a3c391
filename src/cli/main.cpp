// casteljau: command-line tool. A thin shell over the library: parse options, call the library,
// map errors to exit codes (1: bad data, 2: bad usage) with a one-line message on stderr.
#include <cstdio>
#include <exception>
#include <iostream>

#include "casteljau/error.hpp"
#include "cli/cli.hpp"

int main(int argc, char** argv) {
    using namespace casteljau;
    CLI::App app{"casteljau: vector outlines to anti-aliased PNG (exact-area rasterizer)", "casteljau"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "casteljau 0.1.0");
    // Subcommands: one registration function per src/cli/cmd_*.cpp file.
    cli::register_path(app);
    cli::register_svg(app);
    cli::register_bezier(app);
    cli::register_spline(app);
    cli::register_surface(app);
    cli::register_text(app);
    cli::register_map(app);
    cli::register_tiles(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "casteljau: error: " << e.what() << " (see casteljau --help)\n";
        return 2;
    } catch (const cli::UsageError& e) {
        std::cerr << "casteljau: error: " << e.what() << "\n";
        return 2;
    } catch (const Error& e) {
        std::cerr << "casteljau: error: " << e.what() << "\n";
        return e.kind() == ErrorKind::InvalidArgument ? 2 : 1;
    } catch (const std::bad_alloc&) {
        std::cerr << "casteljau: error: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "casteljau: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
