#pragma once
// The solve options every solving subcommand shares (solve, render, bench), spelled once.
#include <CLI/CLI.hpp>
#include <string>

#include "solver/scene/solve_options.h"

namespace radmesh::cli {

struct SolveFlags {
  std::string scene = "office";
  double cellM = 0.381;
  std::string backend = "native";
  std::string projection = "plane";
  std::string mapping = "hierarchical";
  SolveOptions options;

  // Parses the text flags into options and validates them (throws OptionError).
  SolveOptions resolved() const;
};

// Adds SCENE and --backend --cell --projection --resolution --ratio --shooters --until
// --max-iterations --threads --cache-mb to a subcommand.
void addSolveFlags(CLI::App* cmd, SolveFlags& flags);

}  // namespace radmesh::cli
