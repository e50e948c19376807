// radmesh: progressive radiosity on an emulated mesh computer. Subcommands live in cli/*_command.cpp.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>

#include "cli/commands.h"
#include "cli/distributed_command.h"
#include "cli/interrupt.h"
#include "cli/option_checks.h"
#include "cli/usage_failure.h"
#include "solver/scene/scene_error.h"

int main(int argc, char** argv) {
  // A line at a time into a pipe or a file too (tee, nohup): progress is not held until exit.
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  if (const std::string option = radmesh::cli::optionWithEmptyValue(argc, argv); !option.empty()) {
    fmt::print(stderr, "radmesh: error: {} is given an empty value: give it a value, or leave it out\n", option);
    return 2;
  }
  // Under mpirun every process runs the command: without --distributed each would do all of it and
  // write the same files, racing.
  if (const radmesh::cli::Launch launch = radmesh::cli::mpiLaunch();
      launch.processes > 1 && std::none_of(argv, argv + argc, [](const char* a) { return std::string(a) == "--distributed"; })) {
    if (launch.rank == 0)
      fmt::print(stderr,
                 "radmesh: error: this is one of {} processes of an MPI launch, without --distributed: each would run "
                 "the whole command and write the same files; add --distributed (solve and bench solve, with "
                 "--cells auto or --backend mesh), or run radmesh without mpirun\n",
                 launch.processes);
    return 2;
  }
  CLI::App app{"radmesh: view-independent diffuse global illumination (Varshney & Prins)"};
  app.require_subcommand(1);
  app.failure_message(radmesh::cli::usageFailure("radmesh"));
  radmesh::cli::addInfoCommand(app);
  radmesh::cli::addSolveCommand(app);
  radmesh::cli::addRenderCommand(app);
  radmesh::cli::addBenchCommand(app);
  radmesh::cli::addPlotCommand(app);
  // Under mpirun every process meets the same usage error before the run splits: rank 0 says it.
  const bool says = radmesh::cli::mpiLaunch().rank == 0;
  auto fail = [says](const char* what, int code) {
    if (says) fmt::print(stderr, "radmesh: error: {}\n", what);
    return code;
  };
  try {
    std::vector<std::string> arguments = radmesh::cli::decimalArguments(app, argc, argv);
    app.parse(arguments);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the message (or the help) and gives each kind of usage error its own code;
    // every usage error exits 2, as radmesh's own option and scene errors do.
    const int code = says ? app.exit(e) : e.get_exit_code();
    return code == 0 ? 0 : 2;
  } catch (const radmesh::cli::Interrupted&) {
    return 130;  // what was saved, or lost, is said
  } catch (const radmesh::SceneError& e) {
    return fail(e.what(), 2);
  } catch (const radmesh::OptionError& e) {
    return fail(e.what(), 2);
  } catch (const std::exception& e) {
    return fail(e.what(), 1);
  }
  return 0;
}
