#pragma once
// Each subcommand of `radmesh` registers itself on the CLI11 app; main() only wires them.
#include <CLI/CLI.hpp>

namespace radmesh::cli {

void addInfoCommand(CLI::App& app);    // cli/info_command.cpp
void addSolveCommand(CLI::App& app);   // cli/solve_command.cpp
void addRenderCommand(CLI::App& app);  // cli/render_command.cpp (needs the viewer's OSMesa path)
void addBenchCommand(CLI::App& app);   // cli/bench_command.cpp
void addPlotCommand(CLI::App& app);    // cli/plot_command.cpp

}  // namespace radmesh::cli
