// casteljau: command-line tool. A thin shell over the library (see run.cpp).
#include <csignal>
#include <iostream>

#include "cli/run.hpp"

int main(int argc, char** argv) {
    // Past a file-size limit (ulimit -f) the kernel sends SIGXFSZ, whose default action kills the
    // process without a word and leaves the temporary file behind; ignored, the write fails with
    // EFBIG and the writer reports it and removes its temporary file.
    std::signal(SIGXFSZ, SIG_IGN);
    return casteljau::cli::run(argc, argv, true, std::cout, std::cerr);
}
