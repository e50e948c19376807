#include "solver/radiosity/checkpoint.h"

#include <fmt/format.h>

#include <bit>
#include <climits>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "solver/io/atomic_file.h"
#include "solver/io/file_signature.h"
#include "solver/io/output_path.h"
#include "solver/radiosity/checkpoint_identity.h"
#include "solver/radiosity/checkpoint_io.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

using namespace checkpoint_io;

// The file: magic (8 bytes), version (u32), payload size (u64), FNV-1a 64 of the payload (u64),
// payload. Numbers are little-endian as the host keeps them, doubles bitwise.
static_assert(std::endian::native == std::endian::little, "checkpoints are written little-endian");

namespace {

constexpr std::string_view kMagic = kCheckpointSignature;
constexpr std::size_t kHeaderBytes = kMagic.size() + sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t);
constexpr const char* kStartOver = "resume from an earlier checkpoint, or solve from scratch without --resume";

// What a checkpoint of one solve holds besides the header; in a cells checkpoint, each cell's.
struct Contents {
  Identity identity;
  SolverProgress progress;
};

// A cell of a cells solve as the partition made it: what a resume must find again.
struct CellEntry {
  std::string name;
  std::int64_t patches = 0;
  std::int64_t portalPatches = 0;
};

// What a checkpoint of a cells solve holds: the building's identity (its options with the cells'
// settings), its cells, the rounds so far, the lights' ledger and each cell's Contents as bytes.
struct CellsContents {
  Identity identity;
  std::vector<CellEntry> cells;
  std::int64_t rounds = 0;
  Ledger lights;
  std::vector<std::string> cellStates;
};

// The payload starts with what solve it is of.
constexpr const char* kOneSolve = "solve";
constexpr const char* kCellsSolve = "cells";

// The contents' field lists, in the order the file holds them (the values': checkpoint_io.h).
template <class Io> void transfer(Io& io, Contents& c) {
  Identity& i = c.identity;
  SolverProgress& p = c.progress;
  fields(io, i.sceneHash, i.sceneSource, i.patches, i.options, p.radiosity, p.unshotRadiosity, p.unshotPowerW,
         p.timesShot, p.ledger, p.history, p.firstShotPowerW, p.convergence, p.exhausted, p.machineState,
         p.cachedRows, p.elementRadiosity, p.elementLevels, p.shotTotal, p.portalPower, p.portalUnshot);
}
template <class Io> void transfer(Io& io, CellEntry& c) { fields(io, c.name, c.patches, c.portalPatches); }
template <class Io> void transfer(Io& io, CellsContents& c) {
  Identity& i = c.identity;
  fields(io, i.sceneHash, i.sceneSource, i.patches, i.options, c.cells, c.rounds, c.lights, c.cellStates);
}

std::string errnoText() { return std::strerror(errno); }

// An atomic write's failure as the checkpoint's, with the fix.
template <class Write> void writeOrRefuse(const std::string& path, Write write) {
  try {
    write();
  } catch (const std::runtime_error& e) {
    throw CheckpointWriteError(path, e.what());
  }
}

std::vector<CellEntry> cellsOf(const CellSolver& solver) {
  std::vector<CellEntry> cells;
  for (const CellFigures& cell : solver.cellFigures()) cells.push_back({cell.name, cell.patches, cell.portalPatches});
  return cells;
}

}  // namespace

namespace {

// The file: header, then the payload (what solve it is of, then its contents).
void writeFile(const std::string& path, std::string kind, const std::string& contents) {
  Writer payload;
  transfer(payload, kind);
  payload.bytes += contents;
  Writer file;
  file.bytes += kMagic;
  std::uint32_t version = kCheckpointVersion;
  std::uint64_t size = payload.bytes.size();
  std::uint64_t checksum = fnv1a(payload.bytes.data(), payload.bytes.size());
  file.scalar(version);
  file.scalar(size);
  file.scalar(checksum);
  writeOrRefuse(path, [&] { writeAtomically(path, file.bytes + payload.bytes); });
}

SceneError refusal(const std::string& path, const std::string& problem, const std::string& fix) {
  return SceneError(path, "", problem, fix);
}

// The contents of the checkpoint at path, of a solve of `kind`, its header and checksum checked.
// Throws SceneError naming the file, what is wrong and the fix.
template <class T> T readFile(const std::string& path, const std::string& kind) {
  auto refuse = [&](const std::string& problem, const std::string& fix) { return refusal(path, problem, fix); };
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw refuse("is a folder, not a checkpoint", "give --resume a checkpoint written by --checkpoint");
  // A device would be read for ever and a pipe blocks the open: only a file has a size to check.
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
    throw refuse("is not a regular file (a device, a pipe or a socket)", "give --resume a checkpoint written by --checkpoint");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw refuse("cannot be read: " + errnoText(), "give --resume a checkpoint written by --checkpoint");
  const std::uintmax_t fileBytes = std::filesystem::file_size(path, error);
  std::string head(kHeaderBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (!std::string_view(head).starts_with(kMagic))
    throw refuse("is not a radmesh checkpoint (it does not start with RADMESHC)",
                 "give --resume a checkpoint written by --checkpoint");
  Reader header(std::string_view(head).substr(kMagic.size()));
  std::uint32_t version = 0;
  std::uint64_t size = 0, checksum = 0;
  try {
    header.scalar(version);
    header.scalar(size);
    header.scalar(checksum);
  } catch (const Malformed&) {
    throw refuse(fmt::format("is truncated: {} bytes, shorter than its {}-byte header", head.size(), kHeaderBytes),
                 kStartOver);
  }
  if (version != kCheckpointVersion)
    throw refuse(fmt::format("is a version {} checkpoint (or its header is damaged); this radmesh reads version {}",
                             version, kCheckpointVersion),
                 "resume with the radmesh that wrote it, or solve from scratch without --resume");
  // The size before the payload is read: a damaged header must not ask for terabytes.
  if (fileBytes - kHeaderBytes != size)
    throw refuse(fmt::format("is truncated or has bytes appended: {} bytes, its header says {}", fileBytes,
                             kHeaderBytes + size),
                 kStartOver);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (static_cast<std::uint64_t>(in.gcount()) != size)
    throw refuse(fmt::format("is truncated: {} of its {} bytes could be read", kHeaderBytes + in.gcount(),
                             kHeaderBytes + size),
                 kStartOver);
  const std::string_view payload = bytes;
  if (fnv1a(payload.data(), payload.size()) != checksum)
    throw refuse("is corrupted: its checksum does not match its contents", kStartOver);
  std::string savedKind;
  try {
    Reader reader(payload);
    transfer(reader, savedKind);
    if (savedKind == kind) return parsed<T>(reader.rest());
  } catch (const Malformed&) {
  }
  if (savedKind != kind && (savedKind == kOneSolve || savedKind == kCellsSolve))
    throw refuse(savedKind == kCellsSolve ? "is a checkpoint of a cells solve (--cells auto), not of one solve"
                                          : "is a checkpoint of one solve (--cells off), not of a cells solve",
                 fmt::format("resume it with --cells {}, or solve from scratch without --resume",
                             savedKind == kCellsSolve ? "auto" : "off"));
  throw refuse("is corrupted: its contents do not parse although its checksum matches", kStartOver);
}

void restore(const std::string& path, Contents saved, ProgressiveSolver& solver) {
  checkSameSolve(path, saved.identity, identityOf(solver), solver.options());
  try {
    solver.restoreProgress(std::move(saved.progress));
  } catch (const std::invalid_argument& e) {
    throw refusal(path, fmt::format("is corrupted: {}", e.what()), kStartOver);
  }
}

// "12 cells there, 11 here", or the first cell that differs; empty if none.
std::string cellDifferences(const std::vector<CellEntry>& was, const std::vector<CellEntry>& now) {
  if (was.size() != now.size()) return fmt::format("{} cells there, {} here", was.size(), now.size());
  for (size_t c = 0; c < was.size(); ++c)
    if (was[c].name != now[c].name || was[c].patches != now[c].patches || was[c].portalPatches != now[c].portalPatches)
      return fmt::format("cell {} is {} of {} patches and {} portal patches there, {} of {} and {} here", c, was[c].name,
                         was[c].patches, was[c].portalPatches, now[c].name, now[c].patches, now[c].portalPatches);
  return {};
}

}  // namespace

CheckpointWriteError::CheckpointWriteError(const std::string& path, const std::string& reason)
    : std::runtime_error(fmt::format(
          "cannot write checkpoint {}: {} (fix: give --checkpoint a path in a writable folder with room)", path, reason)),
      reason_(reason) {}

void writeCheckpoint(const std::string& path, const ProgressiveSolver& solver) {
  Contents contents{identityOf(solver), solver.progress()};
  writeFile(path, kOneSolve, bytesOf(contents));
}

bool holdsSomethingElse(const std::string& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error) && std::filesystem::file_size(path, error) > 0 &&
         !fileStartsWith(path, kCheckpointSignature);
}

void checkCheckpointWritable(const std::string& path) {
  if (holdsSomethingElse(path))
    throw OptionError(fmt::format("--checkpoint '{}' is a file that is not a radmesh checkpoint: writing the "
                                  "checkpoint would replace it; give a new path, or a checkpoint's",
                                  path));
  checkOutputPath("--checkpoint", path, "", "");  // a missing or unwritable folder, or a folder in its place
}

void resumeFromCheckpoint(const std::string& path, ProgressiveSolver& solver) {
  restore(path, readFile<Contents>(path, kOneSolve), solver);
}

void writeCellsCheckpoint(const std::string& path, const Scene& scene, const CellSolver& solver) {
  std::vector<std::string> cellStates(static_cast<size_t>(solver.cellCount()));
  for (int c = 0; c < solver.cellCount(); ++c) {
    if (!solver.solvesHere(c)) continue;
    Contents cell{identityOf(solver.cellSolver(c)), solver.cellSolver(c).progress()};
    cellStates[c] = bytesOf(cell);
  }
  cellStates = solver.gatherOnFirst(std::move(cellStates));
  if (!solver.writesHere()) return;
  CellsContents contents{identityOf(scene, solver), cellsOf(solver), solver.rounds(), solver.lightsLedger(),
                         std::move(cellStates)};
  writeFile(path, kCellsSolve, bytesOf(contents));
}

void resumeCellsFromCheckpoint(const std::string& path, const Scene& scene, CellSolver& solver) {
  CellsContents saved = readFile<CellsContents>(path, kCellsSolve);
  checkSameSolve(path, saved.identity, identityOf(scene, solver), solver.options());
  if (const std::string differences = cellDifferences(saved.cells, cellsOf(solver)); !differences.empty())
    throw refusal(path, "was written for other cells: " + differences,
                  "resume with the radmesh, scene and options it was written with, or solve from scratch without "
                  "--resume");
  if (saved.cellStates.size() != saved.cells.size() || saved.rounds < 0 || saved.rounds > INT_MAX)
    throw refusal(path, "is corrupted: its cells' states do not match its cells", kStartOver);
  // This process's cells parsed and checked before any is restored.
  std::vector<Contents> cells(saved.cells.size());
  for (int c = 0; c < solver.cellCount(); ++c) {
    if (!solver.solvesHere(c)) continue;
    try {
      cells[c] = parsed<Contents>(saved.cellStates[c]);
    } catch (const Malformed&) {
      throw refusal(path, fmt::format("is corrupted: the state of cell {} does not parse", c), kStartOver);
    }
    checkSameSolve(path, cells[c].identity, identityOf(solver.cellSolver(c)), solver.cellSolver(c).options());
  }
  solver.restoreProgress(static_cast<int>(saved.rounds), saved.lights, [&](int cell, ProgressiveSolver& cellSolver) {
    restore(path, std::move(cells[cell]), cellSolver);
  });
}

}  // namespace radmesh
