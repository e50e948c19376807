#pragma once
// What a user chooses for a solve; shared by the CLI, the viewer and the benchmarks.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace radmesh::emu {
class Transport;  // emulator/transport.h: only the mesh back end sees it (tests/solver/layering_test.cpp)
}

namespace radmesh {

enum class Projection { Plane, Hemicube, Analytic };
enum class Backend { Native, Mesh };
// How the mesh backend lays the single plane over the PEs (solver/projection/plane_mapping.h).
enum class MappingKind { Hierarchical, CutAndStack, Adaptive };
// Which effects the solver simulates (solver/radiosity/effects_plan.h).
enum class EffectsMode { Auto, All };
// Whether patches are cut into elements that receive (solver/meshing/elements.h).
enum class Subdivide { Off, Uniform, Adaptive };
// How a shot's row over elements is made (solver/formfactors/element_shares.h): Rasterise z-buffers
// every element into the item buffer; Share z-buffers the patches and shares each patch's form factor
// among its elements (native back end only); Auto: Share on the native back end, Rasterise on the mesh.
enum class ElementRows { Auto, Rasterise, Share };

// The mesh back end's emulated machine: PE columns x rows, powers of two (the mesh sorts on its
// torus), and each PE's memory (the paper's MP-1: 64 x 64 PEs of 16 KB).
struct PeMachine {
  int cols = 64;
  int rows = 64;
  int memoryKb = 16;
};

struct SolveOptions {
  Backend backend = Backend::Native;
  Projection projection = Projection::Plane;
  MappingKind mapping = MappingKind::Hierarchical;  // mesh backend only
  PeMachine machine;                                // mesh backend only: --pe-grid, --pe-memory
  // Mesh backend only: the processes its machine is split over (--distributed; distributed/ makes
  // it over MPI), every process running the same solve. Null: this process holds the whole machine.
  std::shared_ptr<emu::Transport> meshTransport;
  int resolution = 128;    // N: the single plane (or each hemicube face) is N x N pixels, 16..2048
  double ratio = 3.0;      // half-side of the single plane at height 1 (the paper's ratio 3)
  int shooters = 1;        // k: shooters per iteration, all shot from the same state
  double until = 0.95;     // stop when convergence C reaches this
  // Also stop when the unshot power falls to this fraction of the emitted (0: off). C follows the
  // shooter's power alone; this follows what is actually left to distribute (docs/accuracy.md).
  double untilUnshot = 0.0;
  int maxIterations = 1'000'000;
  int threads = 0;         // 0: every core
  // 0: no form-factor row cache. The CLI gives the native back end defaultFormFactorCacheBytes():
  // there a cached row is bitwise the row projected again, so the cache costs memory, not accuracy.
  std::size_t formFactorCacheBytes = 0;
  bool ambient = true;     // display-only ambient term (Cohen et al. 1988)
  // Patches projecting to less than a pixel get analytic form factors with item-buffer
  // visibility (solver/formfactors/sub_pixel_receivers.h); false: pixel centres only, as in the paper.
  bool subPixelReceivers = true;
  // Auto: only the effects the scene calls for, each skip exact; All: every effect. The library
  // defaults to All, so a caller gets the full simulation unless it asks; the CLI and the viewer
  // default to auto.
  EffectsMode effects = EffectsMode::All;
  // Uniform: patches shoot, elements receive (substructuring, Cohen et al. 1986): each patch is cut
  // into elements no longer than minElementM along any edge. Off: patches shoot and receive.
  // Adaptive (Cohen, Chen, Wallace & Greenberg 1988): each patch starts as one element, and an
  // element splits in four where the light changes across it (docs/accuracy.md), down to elements
  // no shorter than minElementM along their longest edge.
  Subdivide subdivide = Subdivide::Off;
  double minElementM = 0.0;  // uniform: 0 cuts every patch once along each edge (into four); adaptive: > 0
  ElementRows elementRows = ElementRows::Auto;  // --element-rows
  // Adaptive: an element splits where its reflected radiosity and a neighbour's differ by more
  // than this fraction of the brightest element's (the gradient criterion), ...
  double splitContrast = 0.1;
  // ... and where a strong shooter's visibility changes across it (its corners disagree on which
  // points of the shooter they see: a shadow edge).
  bool splitShadows = true;
  // Adaptive: what a split element's children receive anew by their own form factors. False
  // (--split-regather last): the shots of the iteration that split it; what came before they
  // inherit from the parent, evenly. True (all): every shot so far (one row per past shooter).
  bool splitRegatherAll = false;
};

// Named settings (docs/accuracy.md): Bake, what a user can trust (the CLI's default: the
// hemicube at 256², until 1 % of the emitted power is unshot); Paper, Varshney & Prins's (the
// single plane at ratio 3 and 128², k = 1, until C = 0.95); both on the cell the scene's size
// gives. Elements, a better picture than the bake's in a third of its time or less: the bake, but
// patches kElementsCellScale times that cell shoot and uniform elements a quarter of theirs
// receive (the CLI sets both sizes: cli/solve_flags.h). A preset sets the
// projection, resolution, ratio, shooters, stopping rule and subdivision, nothing else.
enum class Preset { Bake, Paper, Elements };
inline constexpr double kElementsCellScale = 2.625;
// --preset elements' patch cell for a scene whose size gives `sceneCellM`: kElementsCellScale times
// it, to two significant figures (the paper's 0.381 m becomes 1 m). Models are drawn in round
// measures, and a cell off them by a hair would cut a sliver along every edge on a grid line.
double elementsPresetCell(double sceneCellM);
void applyPreset(Preset preset, SolveOptions& options);
// The memory this process may use, in bytes: the machine's, or less where a container or batch
// scheduler's cgroup or `ulimit -v` caps it; 0 where it cannot be told.
std::size_t usableMemoryBytes();
// The form-factor cache a solve on the host gets unless told: 1 GiB, or a quarter of this
// machine's memory where that is less (docs/accuracy.md, Defaults).
std::size_t defaultFormFactorCacheBytes();
// --cache-mb as given (MiB; throws OptionError out of [0, 1e6)), or when not given the back end's
// default: defaultFormFactorCacheBytes() on the host; none on the mesh, whose rows would live on
// 16 KB PEs and where a row computed beside other shooters differs in its last bits.
std::size_t formFactorCacheBytes(Backend backend, std::optional<double> givenMb);
// A --cache-mb as given, refused (OptionError) where formFactorCacheBytes would refuse it: for
// option parsers, so that a bad size stops a command before anything runs.
double checkedCacheMb(double givenMb);
const char* toString(Preset preset);
Preset parsePreset(const std::string& text);  // throws OptionError

// Throws OptionError naming the option and the accepted range.
void validateOptions(const SolveOptions& options);
// Throws OptionError for a flag among `given` (e.g. "--ratio") that shapes what the solve `o` (with
// `cellsOn`: --cells auto) does not run, naming the flag to add: it would be dropped without a word.
void refuseFlagsThatShapeNothing(const std::vector<std::string>& given, const SolveOptions& o, bool cellsOn);
// Throws OptionError, naming `option`, for an N x N projection outside 16..2048.
void checkResolution(int resolution, const std::string& option);
// Throws OptionError unless --min-element is a finite length of at least 0.
void checkMinElement(double minElementM);
// Throws OptionError for adaptive subdivision without a minElementM above 0. Not in validateOptions:
// the CLI and the viewer check their flags before the scene is read, and choose the default
// (defaultMinElement) once its cell is known. The solvers check it.
void checkAdaptiveMinElement(const SolveOptions& options);
// Adaptive subdivision given no minElementM splits down to a quarter of the meshing cell:
// docs/accuracy.md measures finer splits scoring worse on every scene. True when it set it.
bool defaultMinElement(SolveOptions& options, double cellM);
// What the user is told of a --min-element taken as a quarter of the cell.
std::string quarterMinElementNote(double minElementM);

const char* toString(Projection projection);
// The projection as a solve reports it: with its N x N, which analytic form factors do not have.
std::string projectionText(Projection projection, int resolution);
const char* toString(Backend backend);
Projection parseProjection(const std::string& text);  // throws OptionError
Backend parseBackend(const std::string& text);        // throws OptionError
const char* toString(MappingKind kind);
MappingKind parseMapping(const std::string& text);    // throws OptionError
const char* toString(EffectsMode mode);
EffectsMode parseEffects(const std::string& text);    // throws OptionError
// --cells: "auto" (find the rooms and solve them cell by cell, docs/cells.md) is true, "off" false.
bool parseCells(const std::string& text);             // throws OptionError
// --pe-grid COLSxROWS into machine.cols and rows (checked by validateOptions); throws OptionError
// naming the form when the text is not two whole numbers joined by x.
void parsePeGrid(const std::string& text, PeMachine& machine);
std::string peGridText(const PeMachine& machine);  // "64x64"
const char* toString(Subdivide subdivide);
Subdivide parseSubdivide(const std::string& text);    // throws OptionError
const char* toString(ElementRows rows);
ElementRows parseElementRows(const std::string& text);  // throws OptionError
// What --element-rows comes to for these options: Share where the back end shares patches' form
// factors among their elements, else Rasterise (never Auto). Checkpoints and --stats record it.
ElementRows resolvedElementRows(const SolveOptions& options);

}  // namespace radmesh
