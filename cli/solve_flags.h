#pragma once
// The solve options every solving subcommand shares (solve, render), spelled once.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "solver/scene/solve_options.h"
#include "solver/scene/up_axis.h"

namespace radmesh::cli {

struct SolveFlags {
  SolveFlags();  // the bake preset (docs/accuracy.md)
  std::string scene = "office";
  double cellM = 0.381;
  std::string backend = "native";
  std::string projection;
  std::string mapping = "hierarchical";
  bool strict = false;  // --strict: a scene that needed any repair is refused
  UpChoice up = UpChoice::Format;  // --up
  SolveOptions options;
  std::vector<const CLI::Option*> solverOptions;  // every flag below but SCENE, to tell which were given

  // Parses the text flags into options and validates them (throws OptionError). With --backend mesh
  // and no --projection, the projection is the single plane, the only one the mesh runs.
  SolveOptions resolved() const;
  // The solver flags given on the command line, e.g. {"--resolution", "--preset"}.
  std::vector<std::string> given() const;
};

// Adds SCENE, --strict, --up and --preset --backend --cell --projection --resolution --ratio --shooters --until
// --until-unshot --max-iterations --threads --cache-mb to a subcommand. --preset is applied as it
// is parsed, the others after parsing: an explicit flag wins over the preset wherever it stands.
void addSolveFlags(CLI::App* cmd, SolveFlags& flags);

}  // namespace radmesh::cli
