// The one hierarchy pipeline (mesh/PrepareHierarchy.h): nesting (and, for VTK's metadata boxes,
// alignment) refused with the level and block named, the metadata boxes of blocks not loaded here
// accepted as parents, cell states and the leaf value range (refined cells and holes excluded,
// independent of threads), a refused hierarchy left unchanged, the log-scale rule, and scene files
// checked the same way.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "io/SceneFile.h"
#include "mesh/PrepareHierarchy.h"

#include <cmath>
#include <stdexcept>
#include <string>

using namespace amrdm;

namespace
{
/// Level 0: 4^3 cells of value 1 + x (cell index), level 1 (ratio 2): the 4^3 cells over level-0
/// cells 0..1 at `lower1` (level-1 cells), value 100.
AmrHierarchy twoLevels(glm::ivec3 lower1 = glm::ivec3(0))
{
  AmrHierarchy h;
  h.ratio = { 1, 2 };
  AmrBlock coarse;
  coarse.level = 0;
  coarse.dims = glm::ivec3(4);
  for (int i = 0; i < 64; ++i)
    coarse.values.push_back(1.0f + float(i % 4));
  AmrBlock fine;
  fine.level = 1;
  fine.lower = lower1;
  fine.dims = glm::ivec3(4);
  fine.values.assign(64, 100.0f);
  h.blocks = { coarse, fine };
  return h;
}

std::string refusal(AmrHierarchy h, const LevelBoxes* metadata = nullptr)
{
  try
  {
    prepareHierarchy(h, 1, metadata);
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  return "";
}
} // namespace

TEST_CASE("a nested hierarchy: cell states, the leaf value range, holes, any thread count")
{
  AmrHierarchy h = twoLevels();
  h.blocks[0].values[63] = std::nanf(""); // a leaf of level 0 (x = 3): a hole
  const HierarchySummary one = prepareHierarchy(h, 1);
  CHECK(one.nonFiniteValues == 1);
  CHECK(h.blocks[0].state[0] == CellRefined); // under the fine block
  CHECK(h.blocks[0].state[63] == CellHidden);
  CHECK(one.valueRange[0] == 1.0); // x = 0 is refined at y, z < 2 only
  CHECK(one.valueRange[1] == 100.0);
  AmrHierarchy again = twoLevels();
  again.blocks[0].values[63] = std::nanf("");
  const HierarchySummary four = prepareHierarchy(again, 4);
  CHECK(four.valueRange[0] == one.valueRange[0]);
  CHECK(four.valueRange[1] == one.valueRange[1]);
  CHECK(four.nonFiniteValues == one.nonFiniteValues);
}

TEST_CASE("alignment and nesting are refused naming the level and block; nothing is changed")
{
  // VTK's AMR (the intake's metadata boxes) requires aligned boxes; a hierarchy made in Kernels
  // may split a refined region at any finer cell, so only its nesting is checked.
  const AmrHierarchy shifted = twoLevels(glm::ivec3(1, 0, 0));
  CHECK(refusal(shifted).empty());
  const LevelBoxes shiftedBoxes = levelBoxesOf(shifted);
  const std::string misaligned = refusal(shifted, &shiftedBoxes);
  CHECK(misaligned.find("level 1 block 0") != std::string::npos);
  CHECK(misaligned.find("not aligned with level 0's cells") != std::string::npos);
  CHECK(misaligned.find("refinement ratio 2") != std::string::npos);

  const std::string outside = refusal(twoLevels(glm::ivec3(6, 0, 0))); // level-0 cells 3..4
  CHECK(outside.find("level 1 block 0 is not properly nested") != std::string::npos);
  CHECK(outside.find("8 of the 8 level-0 cells") == std::string::npos);
  CHECK(outside.find("4 of the 8 level-0 cells") != std::string::npos);

  AmrHierarchy h = twoLevels(glm::ivec3(6, 0, 0));
  CHECK_THROWS_AS(prepareHierarchy(h), std::invalid_argument);
  CHECK(h.blocks[0].state.empty()); // refused before any cell state was written
  CHECK_THROWS_AS(checkHierarchy(h), std::invalid_argument);

  // validate() runs first: a block on an unknown level is its message, not the nesting check's.
  AmrHierarchy unknown = twoLevels();
  unknown.blocks[1].level = 5;
  CHECK(refusal(unknown).find("level") != std::string::npos);
  CHECK(refusal(unknown).find("nested") == std::string::npos);
}

TEST_CASE("metadata boxes: a parent that is not loaded here still nests its children")
{
  // Level 0 is two boxes of 4^3 (x 0..3 and 4..7); only the first is loaded here, and the fine
  // block refines level-0 cells 4..5 (the second box).
  AmrHierarchy h = twoLevels(glm::ivec3(8, 0, 0));
  h.domain.lower = glm::ivec3(0);
  h.domain.upper = glm::ivec3(16, 8, 8);
  CHECK(refusal(h).find("not properly nested") != std::string::npos);
  LevelBoxes metadata = levelBoxesOf(h);
  REQUIRE(metadata.size() == 2);
  CellBox second;
  second.lower = glm::i64vec3(4, 0, 0);
  second.upper = glm::i64vec3(7, 3, 3);
  metadata[0].push_back(second);
  CHECK(refusal(h, &metadata).empty());
  // An invalid (inverted) metadata box is no parent.
  metadata[0].back() = CellBox();
  CHECK(refusal(h, &metadata).find("not properly nested") != std::string::npos);
}

TEST_CASE("the log-scale rule")
{
  CHECK(logScaleValue(100.0) == doctest::Approx(2.0));
  CHECK(logScaleValue(1e-3, -7.0) == doctest::Approx(-3.0));
  CHECK(std::isnan(logScaleValue(0.0)));
  CHECK(std::isnan(logScaleValue(-2.0)));
  CHECK(logScaleValue(-2.0, -7.0) == -7.0f);
  CHECK(logScaleValue(std::nan(""), -7.0) == -7.0f);
}

TEST_CASE("scene files are checked by the same pipeline")
{
  SceneDescription s;
  s.name = "nesting";
  s.hierarchy = twoLevels();
  s.tf.table.assign(2, glm::vec4(1.0f));
  const SceneDescription back = decodeScene(encodeScene(s), "nested.amrdm");
  CHECK(back.hierarchy.blocks.size() == 2);
  s.hierarchy = twoLevels(glm::ivec3(6, 0, 0));
  try
  {
    decodeScene(encodeScene(s), "outside.amrdm");
    FAIL("a scene whose fine block lies outside level 0 was read");
  }
  catch (const SceneFileError& e)
  {
    const std::string what = e.what();
    CHECK(what.find("outside.amrdm") != std::string::npos);
    CHECK(what.find("not properly nested") != std::string::npos);
  }
}
