#pragma once
// The paper's projection and scan-conversion phases (section 1.5) as mesh programs on the
// emulator: every PE projects its own patches onto the shooters' single planes (the solver's
// projection code, so the polygons are the native back end's); stage (a) routes each
// description to the PE owning the upper-left pixel of its bounding box; stage (b) spreads it
// down the xnet into a single-PE-thick strip, each PE accumulating what passes; then the strips
// spread right, and every PE z-buffers each description passing through against the pixels it
// owns (the solver's covers / inverseDepthAt / closer, so the item buffer is the native one).
// Several shooters' planes share the mesh at once, each PE holding its pixels of every plane.
#include <type_traits>
#include <vector>

#include "emulator/pe_array.h"
#include "emulator/wire_size.h"
#include "solver/projection/item_buffer.h"
#include "solver/meshing/patch.h"
#include "solver/projection/plane_mapping.h"
#include "solver/projection/projection.h"
#include "solver/backends/mesh/mesh_shot_stats.h"
#include "solver/projection/scan_conversion.h"

namespace radmesh {

// A patch on its PE: the patch index stands for its geometry and shooter-frame matrix, which
// never change (see the WireSize below). Every process of a distributed machine loads the scene,
// so this static geometry (and the depth-tie ranks made from it) is replicated, not sent.
struct PatchRecord {
  int patch = -1;
};

// What a PE made of one of its patches for one plane of the shot, kept in that PE's memory (not
// charged to its budget: the ledger counts what the scan conversion holds, as it always has).
struct PatchProjection {
  PolygonSetup setup;  // valid where projected
  bool projected = false;
  bool seenFromFront = false;
};

// A projected patch's description in flight. On the MP-1 the set-up travels with it (WireSize
// below charges those bytes); the host moves only its name and reads the set-up its projecting PE
// made (MeshShot::setupOf), which is the same set-up bit for bit at a thirtieth of the copying.
struct Description {
  int patch = -1;
  int plane = 0;  // which of the shot's planes it lies on
  int stepsLeft = 0;
};
static_assert(std::is_trivially_copyable_v<Description>, "descriptions travel between processes as bytes");
static_assert(sizeof(Description) == 3 * sizeof(int), "the host moves a name; the set-up stays where it was made");

// One item-buffer pixel on a PE.
struct ZEntry {
  int item = ItemBuffer::kNone;
  double inverseDepth = 0.0;
};

}  // namespace radmesh

// MP-1 sizes of these records (emulator/wire_size.h): what memory and links are charged.
namespace radmesh::emu {
// Geometry in floats: 4 vertices, normal, centroid, area, and the 3 x 4 matrix into the patch's
// projection frame that the paper stores with every patch (section 1.5): 29 floats, 4-byte id.
template <>
struct WireSize<PatchRecord> {
  static constexpr std::int64_t bytes = 29 * 4 + 4;
};
// The set-up as the MP-1 would send it: up to 5 projected vertices (a quad clipped once) as float
// pairs, the 1/depth plane (3 floats), the patch id and depth-tie rank, a 4 x 16-bit bounding box
// (coordinates below 2048 leave 5 bits each spare, which carry the plane), a 16-bit step count.
// The host z-buffers with the whole PolygonSetup (doubles, edges set up) so that the pixels stay
// the native back end's bit for bit.
template <>
struct WireSize<Description> {
  static constexpr std::int64_t bytes = 5 * 8 + 12 + 4 + 4 + 8 + 2;
};
// Patch id and 1/depth, unpadded.
template <>
struct WireSize<ZEntry> {
  static constexpr std::int64_t bytes = 4 + 8;
};
}  // namespace radmesh::emu

namespace radmesh {

// What the mesh holds for one shot of up to k shooters.
struct MeshShot {
  std::vector<int> shooters;
  PlaneMapping mapping;
  // Each PE's projections of its own patches: slot s of PE pe on plane q is
  // projections[(firstSlot[pe] + s) * planes + q]. Only that PE reads them (and the front end,
  // reading PE memory back).
  std::vector<PatchProjection> projections;
  std::vector<int> firstSlot;  // [pe]
  // What a description names: the set-up of each projected (plane, patch), at [plane * patches +
  // patch]; null where not projected. It points into projections, and distributed, for the other
  // processes' patches, into elsewhere: set up again here by the same functions (host work the
  // machine does not do, so not charged).
  std::vector<const PolygonSetup*> setups;
  std::vector<PatchProjection> elsewhere;
  std::size_t patches = 0;

  // setups points into the shot's own vectors: a move keeps them, a copy would not.
  MeshShot() = default;
  MeshShot(MeshShot&&) = default;
  MeshShot& operator=(MeshShot&&) = default;
  MeshShot(const MeshShot&) = delete;
  MeshShot& operator=(const MeshShot&) = delete;
  const PolygonSetup& setupOf(const Description& d) const {
    return *setups[static_cast<std::size_t>(d.plane) * patches + static_cast<std::size_t>(d.patch)];
  }

  PatchProjection& projection(int pe, int slot, int plane) { return projections[index(pe, slot, plane)]; }
  const PatchProjection& projection(int pe, int slot, int plane) const { return projections[index(pe, slot, plane)]; }
  std::size_t index(int pe, int slot, int plane) const {
    return (static_cast<std::size_t>(firstSlot[pe]) + slot) * shooters.size() + plane;
  }
};

// Stage-(a) and stage-(b) depths per PE, counted from what arrived, summed over the passes.
struct ScanDepths {
  std::vector<int> a;
  std::vector<int> b;
  int passes = 1;
};

class MeshScanConversion {
 public:
  // `shooters` give the shots' viewpoints, `patches` (on the PEs) are projected: the same list,
  // or the shooters' elements (solver/meshing/elements.h), which then never skip their own patch.
  MeshScanConversion(emu::MeshMachine& machine, const std::vector<Patch>& shooters,
                     const std::vector<Patch>& patches, const emu::PeArray<PatchRecord>& patchesOnPe,
                     const ProjectionFace& face, double nearDepth);

  // Projection phase: fills shot.projections and shot.setups (shot.shooters set by the caller).
  void project(MeshShot& shot);

  // Stage (a), stage (b) and the rightward spread with z-buffering into the per-PE item buffers.
  // When a PE's descriptions would overflow its memory (the PE raises a global flag on the real
  // machine; here the emulator's MemoryBudgetError), the scan conversion restarts in twice as many
  // passes, pass p taking the patches with index p mod passes; the item buffer carries over from
  // pass to pass. The work of an abandoned attempt stays charged, as the machine did it.
  ScanDepths scanConvert(const MeshShot& shot, MeshShotStats& stats);

  // The plane's item buffer gathered from the PEs (the front end reading PE memory).
  ItemBuffer gatherItemBuffer(const MeshShot& shot, int plane) const;
  // Per PE: planes x (most pixel rows a PE row owns) x (most pixel columns a PE column owns)
  // slots; a PE's own pixel (a-th of its rows, b-th of its columns) of plane q sits in slot
  // q * pixelsPerPlane() + a * columnsPerPe() + b. Unowned slots stay empty.
  const emu::PeArray<ZEntry>& itemBuffers() const { return zBuffer_; }
  int pixelsPerPlane() const { return rowsPerPe_ * columnsPerPe_; }
  int columnsPerPe() const { return columnsPerPe_; }

 private:
  // Patch j's projection onto plane q of the shot (unprojected: seen edge-on, behind, the shooter itself).
  void projectOne(const MeshShot& shot, int j, int q, PatchProjection& p) const;
  void listSetups(MeshShot& shot) const;
  void resetItemBuffers(const MeshShot& shot);
  // Distributed, each process counted its own PEs' depths: the front end reads every PE's.
  void gatherDepths(ScanDepths& depths) const;
  void routeToUpperLeft(const MeshShot& shot, int pass, int passes, ScanDepths& depths);
  void spreadDown(ScanDepths& depths);
  void spreadRight(const MeshShot& shot);
  // z-buffers one description against PE pe's pixels of its plane; returns the pixels tested
  // (those of the PE inside the description's bounding box).
  int zBuffer(const MeshShot& shot, int pe, const Description& description);
  // z-buffers PE pe's descriptions, then keeps (in place) those that must travel further east,
  // each with its remaining steps from `steps`; returns the pixels tested.
  template <class Steps>
  int zBufferAndKeep(const MeshShot& shot, int pe, Steps steps);
  // One step of the rightward spread's z-buffering on every active PE (the first: the strips).
  void zBufferStep(const MeshShot& shot, bool first);

  emu::MeshMachine& machine_;
  const std::vector<Patch>& shooters_;
  const std::vector<Patch>& patches_;
  const emu::PeArray<PatchRecord>& patchesOnPe_;
  ProjectionFace face_;
  double nearDepth_;
  std::vector<int> rank_;
  emu::PeArray<Description> descriptions_;  // (a), then accumulated through (b), then in transit
  emu::PeArray<int> forward_;               // (b): which of a PE's descriptions go on down
  emu::PeArray<ZEntry> zBuffer_;
  int rowsPerPe_ = 0;
  int columnsPerPe_ = 0;
  std::vector<int> pixelTests_;  // per PE, this step
};

}  // namespace radmesh
