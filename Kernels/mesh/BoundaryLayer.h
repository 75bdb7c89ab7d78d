// The dual mesh's clamped boundary layer. The dual cells of an AMR hierarchy end at the hull of
// its cell centres, half a cell short of the domain faces. Lattice positions beyond a face of
// the domain box (AmrHierarchy::domainBox()) therefore resolve to ghosts: virtual copies of the
// boundary leaf that contains the position clamped into the domain, with that leaf's value and
// its centre moved onto the face (or edge, or corner). Dual cells that reach a ghost become
// stitching elements between the hull and the face; the field in them is the boundary leaves'
// interpolant held constant along the face normal (clamped boundary values), so it stays C0,
// level transitions on a face included (the layer is the dual mesh of the face's cells, extruded
// to the face). Faces of a part of the domain (an MPI rank's region) are not domain faces and get
// no ghosts. Host code.
#pragma once

#include "accel/CellLocator.h"
#include "mesh/AmrHierarchy.h"

#include <cstdint>

namespace amrdm
{

class BoundaryLayer
{
public:
  BoundaryLayer(const AmrHierarchy& amr, const CellLocator& locator);

  const CellLocator& locator() const { return this->Locator; }

  /// CellLocator::locate, except that a position beyond a domain face resolves to the ghost of
  /// the leaf containing the clamped position (kind Ghost; Finer or Missing where that is).
  /// `hint`: see CellLocator::locate.
  CellRef locate(int level, const glm::ivec3& c, BlockHint* hint = nullptr) const;

  /// Global id: CellLocator's for cells, ids >= CellLocator::totalCells() for ghosts.
  std::int64_t globalId(const CellRef& ref) const;
  bool isGhost(std::int64_t id) const { return id >= this->Locator.totalCells(); }

  /// Grid-space position of a vertex: a cell's centre, or a ghost's centre on the domain faces.
  glm::dvec3 centre(std::int64_t id) const;
  /// The same for the cell or ghost `ref` names (a Leaf or Ghost from locate(); no id lookup).
  glm::dvec3 centre(const CellRef& ref) const;
  /// A cell's value; a ghost has its cell's value.
  float value(std::int64_t id) const;

private:
  /// Ghost codes: per axis 0 inside, 1 below lower, 2 above upper, axis d weighted by 3^d.
  static constexpr int kCodes = 27;

  const AmrHierarchy& Amr;
  const CellLocator& Locator;
  GridBox Domain;
};

} // namespace amrdm
