#include "cli/app.hpp"

int main(int argc, char** argv) { return hydrodda::cli::run_app(argc, argv); }
