#pragma once
// The solve options every solving subcommand shares (solve, render), spelled once.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/option_checks.h"
#include "solver/io/daylight.h"
#include "solver/meshing/meshing.h"
#include "solver/scene/solve_options.h"
#include "solver/scene/up_axis.h"

namespace radmesh::cli {

struct SolveFlags {
  SolveFlags();  // the bake preset (docs/accuracy.md)
  std::string scene = "office";
  double cellM = kDefaultCellM;  // used when --cell is given; else chooseCell's (cell())
  std::string backend = "native";
  std::string projection;
  std::string mapping = "hierarchical";
  std::string effects = "auto";   // --effects auto|all: simulate only what the scene calls for, or everything
  std::string subdivide = "off";  // --subdivide off|uniform (--min-element is options.minElementM)
  Preset preset = Preset::Bake;   // the last --preset given
  bool strict = false;  // --strict: a scene that needed any repair is refused
  std::string cells = "off";  // --cells auto: solve cell by cell (docs/cells.md)
  int exchangeShots = 16;     // --exchange-shots: iterations per cell between portal exchanges
  int portalBins = 4;         // --portal-bins: direction bins of light crossing a portal (0, 1: diffuse)
  Daylight daylight;          // --sky, --sky-model, --sun
  UpChoice up = UpChoice::Format;  // --up
  double metresPerUnit = 0.0;      // --units; 0: not given
  std::optional<double> cacheMb;   // --cache-mb; unset: the back end's default (formFactorCacheBytes)
  SolveOptions options;
  std::vector<const CLI::Option*> solverOptions;  // every flag below but SCENE, to tell which were given

  // Parses the text flags into options and validates them (throws OptionError). With --backend mesh
  // and no --projection, the projection is the single plane, the only one the mesh runs. No display
  // ambient term: solve and render output what was solved.
  SolveOptions resolved() const;
  bool cellsOn() const;  // --cells auto: parseCells(cells)
  // The solver flags given on the command line, e.g. {"--resolution", "--preset"}.
  std::vector<std::string> given() const;
  // The cell to mesh `scene` with: --cell when given, else the one chosen from the scene's size
  // (with --preset elements, elementsPresetCell of it).
  CellChoice cell(const Scene& scene) const;
  // cell(scene), printing why, and the default --min-element it implies for `options` (adaptive
  // subdivision, or --preset elements, given none: a quarter of the cell).
  CellChoice announceCell(const Scene& scene, SolveOptions& options) const;
};

inline constexpr const char* kPortalBinsHelp =
    "In the cells solve (--cells auto): light crossing a portal keeps its direction in the bins of an N x N hemicube "
    "and goes on in it (docs/cells.md); 0 or 1: re-emitted diffusely (the paper's)";
inline constexpr const char* kExchangeShotsHelp =
    "The cells solve's shots a round between portal exchanges, this many a cell on average, shared by the cells' "
    "unshot power; a focus cell (the viewer's camera's, bench cells' --focus-cell) shoots them alone until its own "
    "unshot is below the stopping rule, then each cell's part halves at each portal from it (docs/cells.md)";
// --exchange-shots and --portal-bins, the same on every command that runs the cells solve.
// Inline: radmesh-view takes them too without linking the commands.
inline void addPortalExchangeOptions(CLI::App* cmd, int& exchangeShots, int& portalBins) {
  cmd->add_option("--exchange-shots", exchangeShots, kExchangeShotsHelp)->check(kPositive)->capture_default_str();
  cmd->add_option("--portal-bins", portalBins, kPortalBinsHelp)->capture_default_str();
}

// --max-iterations, the same on every command that solves.
inline constexpr const char* kMaxIterationsHelp =
    "Stop after this many iterations at most, or sooner at --until/--until-unshot (with --cells auto: every "
    "cell's, checked between rounds)";
inline constexpr const char* kRatioHelp =
    "Half-side of the single plane at height 1 (3, the paper's, catches 91.7 % of each shot)";
inline constexpr const char* kUntilUnshotHelp =
    "Also stop when unshot power is this fraction of the emitted (of what came in, where lights fall on the model's "
    "outside too), e.g. 0.01, once every emitting surface has shot (0: only below 1e-9 of it, what the energy ledger "
    "vouches for)";

inline constexpr const char* kCacheMbHelp =
    "Form-factor row cache budget in MiB (0: none; default: 1024, or a quarter of the memory where that is less, on "
    "the native back end; none on the mesh back end)";

// --cell's value when the user gave it, else chooseCell(scene); `why` says which.
CellChoice commandCell(const Scene& scene, double cellM, bool given);

// Adds --sky LUX, --sky-model uniform|cie-overcast and --sun AZIMUTH,ELEVATION[,LUX] (docs/scene-formats.md#daylight).
void addDaylightFlags(CLI::App* cmd, Daylight& daylight);

// Adds --pe-grid COLSxROWS and --pe-memory KB, the mesh back end's machine (checked by validateOptions).
void addMachineFlags(CLI::App* cmd, PeMachine& machine);

// Adds SCENE with --strict and --up, --sky, --sky-model and --sun, --preset, and the solver's flags
// (--effects --backend --cell --mapping --pe-grid --pe-memory --projection --resolution --ratio --shooters
// --until --until-unshot --max-iterations --threads --cache-mb --subdivide --min-element
// --split-contrast --split-shadows --split-regather --cells --exchange-shots --portal-bins) to a
// subcommand. --preset is applied as it is parsed, the others after parsing: an explicit flag wins
// over the preset wherever it stands.
void addSolveFlags(CLI::App* cmd, SolveFlags& flags);


}  // namespace radmesh::cli
