// SPDX-License-Identifier: MIT
#include "cli.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    return e2d::validation::runCli(args, std::cout, std::cerr);
}
