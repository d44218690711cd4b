// The `dtlab` executable: everything is in dtlab::cli::run (apps/dtlab.cpp).
#include "apps/run.hpp"

int main(int argc, char** argv) { return dtlab::cli::run(argc, argv); }
