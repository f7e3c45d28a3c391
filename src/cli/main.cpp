// casteljau: command-line tool. A thin shell over the library (see run.cpp).
#include <iostream>

#include "cli/cli.hpp"

int main(int argc, char** argv) { return casteljau::cli::run(argc, argv, true, std::cout, std::cerr); }
