// fem2mpm: FEM recorder files + model description -> CB-Geo particle HDF5 + MPM deck (bridge/README.md).
#include <iostream>

#include "bridge/cli.hpp"

int main(int argc, char** argv) { return bridge::run_cli(argc, argv, std::cout, std::cerr); }
