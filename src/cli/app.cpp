#include "cli/app.hpp"

#include <CLI/CLI.hpp>

namespace hydrodda::cli {

int run_app(int argc, char** argv) {
  CLI::App app{"hydrodda: fluid flow through deforming, fractured, blocky rock"};
  app.set_version_flag("--version", "hydrodda 0.1.0");
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  return kSuccess;
}

}  // namespace hydrodda::cli
