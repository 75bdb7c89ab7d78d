// The AMR compatibility layer (Mapper/AMRDualMeshVTKCompat.h) on its own: an AMR built and read
// back through it alone (levels, blocks per level, boxes, spacing, origin, grid description,
// blocks, ghost arrays), and its refusals. Only the layer is called, so the same test checks
// the VTK 9.2 branch here and the VTK 9.6+ branch in scripts/check-vtk-latest.sh --full.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "AMRDualMeshVTKCompat.h"
#include "vtkAMRBox.h"
#include "vtkCellData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOverlappingAMR.h"
#include "vtkUnsignedCharArray.h"

#include <string>

namespace compat = amrdm_vtk::amrcompat;

namespace
{
/// A level-`level` block over cells [lo, lo + n) with spacing h (origin 0).
vtkSmartPointer<vtkImageData> block(const int lo[3], int n, double h)
{
  vtkSmartPointer<vtkImageData> grid = compat::NewBlock();
  grid->SetDimensions(n + 1, n + 1, n + 1);
  grid->SetSpacing(h, h, h);
  grid->SetOrigin(lo[0] * h, lo[1] * h, lo[2] * h);
  return grid;
}

/// Two levels: two 4^3 blocks on level 0, one 4^3 block (ratio 2) on level 1.
vtkSmartPointer<vtkOverlappingAMR> twoLevels()
{
  auto amr = vtkSmartPointer<vtkOverlappingAMR>::New();
  compat::InitializeLevels(amr, { 2U, 1U });
  const double origin[3] = { 0.0, 0.0, 0.0 };
  compat::SetOrigin(amr, origin);
  compat::SetGridDescription(amr, 8); // VTK_XYZ_GRID = VTK_STRUCTURED_XYZ_GRID = 8
  const double h0[3] = { 1.0, 1.0, 1.0 }, h1[3] = { 0.5, 0.5, 0.5 };
  compat::SetSpacing(amr, 0, h0);
  compat::SetSpacing(amr, 1, h1);
  compat::SetRefinementRatio(amr, 0, 2);
  const int lo00[3] = { 0, 0, 0 }, hi00[3] = { 3, 3, 3 };
  const int lo01[3] = { 4, 0, 0 }, hi01[3] = { 7, 3, 3 };
  const int lo10[3] = { 2, 2, 2 }, hi10[3] = { 5, 5, 5 };
  compat::SetBox(amr, 0, 0, vtkAMRBox(lo00, hi00));
  compat::SetBox(amr, 0, 1, vtkAMRBox(lo01, hi01));
  compat::SetBox(amr, 1, 0, vtkAMRBox(lo10, hi10));
  return amr;
}
}

TEST_CASE("no AMR: zero levels and blocks")
{
  CHECK(compat::NumberOfLevels(nullptr) == 0);
  CHECK(compat::NumberOfBlocks(nullptr, 0) == 0);
  vtkImageData* grid = nullptr;
  CHECK(compat::BlockAt(nullptr, 0, 0, grid) == compat::BlockState::Absent);
  CHECK(grid == nullptr);
  CHECK(compat::CellGhosts(nullptr) == nullptr);
}

TEST_CASE("metadata written through the layer reads back through it")
{
  MESSAGE("AMR API: ", compat::APIName());
  vtkSmartPointer<vtkOverlappingAMR> amr = twoLevels();
  CHECK(compat::NumberOfLevels(amr) == 2);
  CHECK(compat::NumberOfBlocks(amr, 0) == 2);
  CHECK(compat::NumberOfBlocks(amr, 1) == 1);
  CHECK(compat::NumberOfBlocks(amr, 2) == 0); // a level out of range
  CHECK(compat::GridDescription(amr) == 8);
  double h[3];
  compat::Spacing(amr, 1, h);
  CHECK(h[0] == 0.5);
  CHECK(h[2] == 0.5);
  const double* o = compat::Origin(amr);
  CHECK(o[0] == 0.0);
  const vtkAMRBox& box = compat::Box(amr, 0, 1);
  CHECK(box.GetLoCorner()[0] == 4);
  CHECK(box.GetHiCorner()[0] == 7);
  CHECK(compat::Box(amr, 1, 0).GetLoCorner()[1] == 2);
  // Metadata only: no block is loaded yet.
  vtkImageData* grid = nullptr;
  CHECK(compat::BlockAt(amr, 0, 0, grid) == compat::BlockState::Absent);
  CHECK(compat::Block(amr, 1, 0) == nullptr);
}

TEST_CASE("blocks stored through the layer are the ones read back")
{
  vtkSmartPointer<vtkOverlappingAMR> amr = twoLevels();
  const int lo00[3] = { 0, 0, 0 }, lo10[3] = { 2, 2, 2 };
  vtkSmartPointer<vtkImageData> coarse = block(lo00, 4, 1.0), fine = block(lo10, 4, 0.5);
  std::string error;
  REQUIRE_MESSAGE(compat::SetBlock(amr, 0, 0, coarse, error), error);
  REQUIRE_MESSAGE(compat::SetBlock(amr, 1, 0, fine, error), error);
  vtkImageData* grid = nullptr;
  CHECK(compat::BlockAt(amr, 0, 0, grid) == compat::BlockState::Image);
  CHECK(grid == coarse.GetPointer());
  CHECK(compat::Block(amr, 1, 0) == fine.GetPointer());
  CHECK(compat::Block(amr, 0, 1) == nullptr); // its box is there, its data is not
  CHECK(compat::Block(amr, 0, 9) == nullptr); // no such block
}

TEST_CASE("SetBlock refuses what VTK would not store, with a message")
{
  vtkSmartPointer<vtkOverlappingAMR> amr = twoLevels();
  const int lo[3] = { 0, 0, 0 };
  std::string error;
  CHECK_FALSE(compat::SetBlock(amr, 0, 7, block(lo, 4, 1.0), error));
  CHECK(error.find("level 0 block 7") != std::string::npos);
  error.clear();
  CHECK_FALSE(compat::SetBlock(amr, 0, 0, nullptr, error));
  CHECK(error.find("level 0 block 0") != std::string::npos);
  if (std::string(compat::APIName()).find("<= 9.5") != std::string::npos)
  {
    // VTK 9.2-9.5 store vtkUniformGrid blocks only; a plain vtkImageData is refused by name.
    vtkNew<vtkImageData> plain;
    plain->SetDimensions(5, 5, 5);
    error.clear();
    CHECK_FALSE(compat::SetBlock(amr, 0, 0, plain, error));
    CHECK(error.find("vtkImageData") != std::string::npos);
    CHECK(compat::Block(amr, 0, 0) == nullptr);
  }
  CHECK(compat::UnsupportedBlockMessage(amr, 1, 0).find("level 1 block 0") != std::string::npos);
}

TEST_CASE("ghost arrays and flags")
{
  const int lo[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkImageData> grid = block(lo, 2, 1.0);
  CHECK(compat::CellGhosts(grid) == nullptr);
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(compat::GhostArrayName());
  ghosts->SetNumberOfTuples(grid->GetNumberOfCells());
  ghosts->FillValue(compat::RefinedCell);
  grid->GetCellData()->AddArray(ghosts);
  CHECK(compat::CellGhosts(grid) == ghosts.GetPointer());
  CHECK(std::string(compat::GhostArrayName()) == "vtkGhostType");
  // The values every VTK since 8.x writes into vtkGhostType (readers and files depend on them).
  CHECK(compat::DuplicateCell == 1);
  CHECK(compat::RefinedCell == 8);
  CHECK(compat::HiddenCell == 32);
}
