// A cells solve split over the run's processes (CellSolver with distributed::MpiCellRanks) equals
// the solve in one process bit for bit: radiosity, ledger, iterations, rounds, per-cell figures.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "distributed/mpi_cell_ranks.h"
#include "solver/cells/find_cells.h"
#include "solver/formfactors/direction_bins.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/cell_solver.h"

namespace radmesh {
namespace {

SolveOptions fastOptions(double untilUnshot) {
  SolveOptions o;
  o.projection = Projection::Hemicube;
  o.resolution = 32;
  o.until = 1.0;
  o.untilUnshot = untilUnshot;
  o.threads = 1;
  return o;
}

void solve(CellSolver& solver) {
  while (!solver.done()) solver.round();
}

void expectSameLedger(const Ledger& a, const Ledger& b) {
  for (size_t t = 0; t < Ledger::kTerms.size(); ++t)
    EXPECT_EQ(a.*Ledger::kTerms[t], b.*Ledger::kTerms[t]) << "ledger term " << t;
}

// Solves `name` in this process alone and over the run's processes, and compares every figure;
// then checks what each process sent: one message a round to each process whose cells share a
// portal with its own, holding the runs of lit direction bins of the portal patches it sends on.
void expectDistributedEqualsOneProcess(const std::string& name, double cellM, int portalBins, double untilUnshot) {
  const Scene scene = builtinScene(name);
  const std::vector<Patch> patches = meshScene(scene, cellM);
  const CellPartition partition = findCells(scene, patches);
  const CellSolveSettings settings{cellM, 16, portalBins};
  CellSolver alone(scene, patches, partition, fastOptions(untilUnshot), settings);
  solve(alone);
  distributed::MpiCellRanks ranks;
  CellSolver split(scene, patches, partition, fastOptions(untilUnshot), settings, &ranks);
  solve(split);

  EXPECT_EQ(split.rounds(), alone.rounds());
  EXPECT_EQ(split.iterations(), alone.iterations());
  expectSameLedger(split.ledger(), alone.ledger());
  const std::vector<Rgb> a = alone.radiosity(), b = split.radiosity();
  ASSERT_EQ(a.size(), b.size());
  size_t differing = 0;
  for (size_t j = 0; j < a.size(); ++j) differing += a[j] != b[j];
  EXPECT_EQ(differing, 0u) << "patches whose radiosity differs";
  EXPECT_EQ(split.displayRadiosity(), alone.displayRadiosity());
  const std::vector<CellFigures> fa = alone.cellFigures(), fb = split.cellFigures();
  ASSERT_EQ(fa.size(), fb.size());
  for (size_t c = 0; c < fa.size(); ++c) {
    EXPECT_EQ(fb[c].iterations, fa[c].iterations) << fa[c].name;
    expectSameLedger(fb[c].ledger, fa[c].ledger);
    EXPECT_EQ(split.owner(static_cast<int>(c)) == ranks.rank(), [&] {
      try {
        split.cellSolver(static_cast<int>(c));
        return true;
      } catch (const std::out_of_range&) {
        return false;
      }
    }()) << "a process makes the solvers of its own cells alone";
  }

  // The full bins: 3 doubles per direction bin per portal patch sent on.
  std::set<int> neighbours;
  long long fullDoubles = 0;
  for (const Portal& portal : partition.portals) {
    const int ownerA = split.owner(portal.cellA), ownerB = split.owner(portal.cellB);
    if (ownerA == ownerB || (ownerA != ranks.rank() && ownerB != ranks.rank())) continue;
    neighbours.insert(ownerA == ranks.rank() ? ownerB : ownerA);
    fullDoubles += 3LL * directionBinCount(portalBins) * static_cast<long long>(meshScene(
        Scene{scene.source, {Material{"portal", Rgb(0.0), Rgb(0.0)}}, {{portal.vertices, 0, "portal"}}, {}, scene.upAxis},
        cellM).size());
  }
  const CellTraffic mine = ranks.traffic().at(ranks.rank());
  EXPECT_EQ(mine.messages, static_cast<long long>(neighbours.size()) * split.rounds());
  EXPECT_EQ(mine.gathers, 2LL * split.rounds() + 3);  // made, twice a round, radiosity and display radiosity
  // What went: each round, a message to each neighbour of its links' runs of lit bins, as the one
  // process recorded them for every link, or the full bins where shorter; less than the full bins.
  const std::vector<PortalLinkTraffic> links = alone.portalTraffic();
  long long doubles = 0;
  for (int round = 0; round < split.rounds(); ++round)
    for (int to : neighbours) {
      size_t runs = 0, linksTo = 0;
      for (const PortalLinkTraffic& link : links)
        if (split.owner(link.cell) == ranks.rank() && split.owner(link.twinCell) == to)
          runs += static_cast<size_t>(link.runDoubles.at(static_cast<size_t>(round))), ++linksTo;
      doubles += static_cast<long long>(portalMessageDoubles(runs, linksTo * directionBinCount(portalBins)));
    }
  EXPECT_EQ(mine.bytes, 8 * doubles);
  EXPECT_LE(mine.bytes, 8 * fullDoubles * split.rounds());
  const std::vector<PortalLinkTraffic> splitLinks = split.portalTraffic();
  ASSERT_EQ(splitLinks.size(), links.size());
  for (size_t k = 0; k < links.size(); ++k) EXPECT_EQ(splitLinks[k].runDoubles, links[k].runDoubles) << "link " << k;
}

TEST(DistributedCells, TwoRoomsEqualsOneProcessBitForBit) { expectDistributedEqualsOneProcess("two-rooms", 0.75, 4, 0.02); }

TEST(DistributedCells, TwoRoomsDiffusePortalsEqualsOneProcessBitForBit) {
  expectDistributedEqualsOneProcess("two-rooms", 0.75, 0, 0.02);
}

// 12 cells (9 rooms, 2 corridors and the outside), 12 rounds at 15 % unshot.
TEST(DistributedCells, Building3x3EqualsOneProcessBitForBit) {
  expectDistributedEqualsOneProcess("building:3x3", 1.5, 2, 0.15);
}

// Elements (--subdivide uniform and adaptive): the building's elements, their radiosity and each
// cell's element count are gathered from their processes, the same as one process's bit for bit.
TEST(DistributedCells, TwoRoomsWithElementsEqualsOneProcessBitForBit) {
  const Scene scene = builtinScene("two-rooms");
  const std::vector<Patch> patches = meshScene(scene, 0.75);
  const CellPartition partition = findCells(scene, patches);
  for (Subdivide how : {Subdivide::Uniform, Subdivide::Adaptive}) {
    SolveOptions o = fastOptions(0.05);
    o.subdivide = how;
    o.minElementM = how == Subdivide::Adaptive ? 0.2 : 0.0;
    CellSolver alone(scene, patches, partition, o, {0.75, 16, 4});
    solve(alone);
    distributed::MpiCellRanks ranks;
    CellSolver split(scene, patches, partition, o, {0.75, 16, 4}, &ranks);
    solve(split);
    EXPECT_EQ(split.iterations(), alone.iterations()) << toString(how);
    expectSameLedger(split.ledger(), alone.ledger());
    const std::vector<Patch> a = alone.elements().elements, b = split.elements().elements;
    ASSERT_EQ(a.size(), b.size()) << toString(how);
    EXPECT_GT(a.size(), patches.size());
    for (size_t e = 0; e < a.size(); ++e) {
      ASSERT_EQ(b[e].vertices, a[e].vertices) << "element " << e;
      ASSERT_EQ(b[e].areaM2, a[e].areaM2) << "element " << e;
      ASSERT_EQ(b[e].polygon, a[e].polygon) << "element " << e;
    }
    EXPECT_EQ(split.elementRadiosity(), alone.elementRadiosity()) << toString(how);
    EXPECT_EQ(split.displayElementRadiosity(), alone.displayElementRadiosity()) << toString(how);
    const std::vector<CellFigures> fa = alone.cellFigures(), fb = split.cellFigures();
    for (size_t c = 0; c < fa.size(); ++c) EXPECT_EQ(fb[c].elements, fa[c].elements) << fa[c].name;
  }
}

}  // namespace
}  // namespace radmesh
