// radmesh: progressive radiosity on an emulated mesh computer. Subcommands live in cli/*_command.cpp.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <string>

#include "cli/commands.h"
#include "cli/option_checks.h"
#include "solver/scene/scene_error.h"

int main(int argc, char** argv) {
  if (const std::string option = radmesh::cli::optionWithEmptyValue(argc, argv); !option.empty()) {
    fmt::print(stderr, "radmesh: error: {} is given an empty value: give it a value, or leave it out\n", option);
    return 2;
  }
  CLI::App app{"radmesh: view-independent diffuse global illumination (Varshney & Prins)"};
  app.require_subcommand(1);
  radmesh::cli::addInfoCommand(app);
  radmesh::cli::addSolveCommand(app);
  radmesh::cli::addRenderCommand(app);
  radmesh::cli::addBenchCommand(app);
  radmesh::cli::addPlotCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the message (or the help) and gives each kind of usage error its own code;
    // every usage error exits 2, as radmesh's own option and scene errors do.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const radmesh::SceneError& e) {
    fmt::print(stderr, "radmesh: error: {}\n", e.what());
    return 2;
  } catch (const radmesh::OptionError& e) {
    fmt::print(stderr, "radmesh: error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "radmesh: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
