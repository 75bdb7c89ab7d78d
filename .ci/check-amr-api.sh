#!/usr/bin/env bash
# Every call of VTK's AMR API in Mapper/ and Plugin/ goes through the compatibility layer
# Mapper/AMRDualMeshVTKCompat.{h,cxx} (issue 36, docs/VTK-COMPAT.md): VTK 9.6 changed the AMR
# data model and VTK master removed the calls of 9.2. Fails naming file:line for any such call
# elsewhere. `check-amr-api.sh --self-test` seeds one call per rule into a scratch copy and
# fails unless every seeded line is reported (so the check itself can fail).
set -u
# The AMR calls, by method name on any receiver but `this` (vtkAMRDualMeshFileCheck has its own
# GetNumberOfLevels/GetNumberOfBlocks), and the AMR-only signatures of shared names.
rules=(
  '(?<!this)(->|\.)\s*(GetNumberOfLevels|GetNumberOfBlocks|GetNumberOfDataSets|GetTotalNumberOfBlocks|GetDataSet|GetDataSetAs\w+|SetDataSet|GetAMRBox|SetAMRBox|[SG]etRefinementRatio|[SG]etGridDescription|GetAMRInfo|GetAMRMetaData|GetOverlappingAMRMetaData|GenerateParentChildInformation|HasChildrenInformation|GetParents|GetChildren|[SG]etAMRBlockSourceIndex|GetAbsoluteBlockIndex|GetCompositeIndex|ComputeIndexPair|GetLevelAndIndex|GetCellGhostArray)\s*\('
  '(->|\.)\s*GetSpacing\s*\(\s*[^,()]+,'
  '(->|\.)\s*SetSpacing\s*\(\s*[^,()]+,\s*[^,()]+\)'
  '(->|\.)\s*GetOrigin\s*\(\s*\)'
  '(->|\.)\s*SetOrigin\s*\(\s*[^,()]+\)'
  '(->|\.)\s*Initialize\s*\(\s*[^)\s]'
  'vtkUniformGrid\s*([*&>]|::)|vtkUniformGrid\.h|class\s+vtkUniformGrid\b|<vtkUniformGrid\b'
  '\b(vtkAMRInformation|vtkAMRUtilities|vtkAMRMetaData|vtkOverlappingAMRMetaData|vtkAMRDataObject|vtkCartesianGrid|vtkUniformGridAMRDataIterator|VTK_XYZ_GRID|VTK_STRUCTURED_XYZ_GRID)\b'
  'vtkDataSetAttributes::(REFINEDCELL|HIDDENCELL|DUPLICATECELL|GhostArrayName)\b'
)
pattern="$(IFS='|'; echo "${rules[*]}")"

scan() { # $1 = root; prints file:line:text of every call outside the layer
  (cd "$1" && find Mapper Plugin -type f \( -name '*.h' -o -name '*.cxx' -o -name '*.cpp' \) \
    ! -name 'AMRDualMeshVTKCompat.*' -print0 2>/dev/null | sort -z |
    xargs -0 -r grep -nHP "$pattern" | grep -vP '^[^:]+:[0-9]+:\s*(//|/?\*)')
}

if [ "${1:-}" = --self-test ]; then
  scratch="$(mktemp -d)"
  trap 'rm -rf "$scratch"' EXIT
  mkdir -p "$scratch/Mapper" "$scratch/Plugin"
  cat > "$scratch/Mapper/Seed.cxx" << 'SEED'
n = amr->GetNumberOfLevels();
n = amr->GetNumberOfDataSets(l);
n = amr->GetNumberOfBlocks(l);
g = amr->GetDataSet(l, i);
g = amr->GetDataSetAsImageData(l, i);
amr->SetDataSet(l, i, g);
b = amr->GetAMRBox(l, i);
amr->SetAMRBox(l, i, b);
amr->SetRefinementRatio(l, 2);
amr->SetGridDescription(d);
amr->GetSpacing(l, h);
amr->SetSpacing(l, h);
o = amr->GetOrigin();
amr->SetOrigin(o);
amr->Initialize(1, &one);
a = g->GetCellGhostArray();
vtkUniformGrid* u = nullptr;
#include "vtkAMRInformation.h"
int d = VTK_XYZ_GRID;
c = vtkDataSetAttributes::REFINEDCELL;
amr->GenerateParentChildInformation();
SEED
  printf '%s\n' 'if (this->GetNumberOfLevels() > 0) // not AMR: our own method' \
    'grid->GetSpacing(h);' 'grid->SetOrigin(x, y, z);' 'output->Initialize();' \
    '// amr->GetDataSet(l, i) in a comment' > "$scratch/Plugin/Clean.cxx"
  seeded=$(wc -l < "$scratch/Mapper/Seed.cxx")
  found=$(scan "$scratch" | grep -c '^Mapper/Seed.cxx:')
  false_hits=$(scan "$scratch" | grep -c '^Plugin/Clean.cxx:')
  if [ "$found" -ne "$seeded" ] || [ "$false_hits" -ne 0 ]; then
    echo "AMRAPICheck self-test: reported $found of $seeded seeded AMR calls and $false_hits of" \
      "5 non-AMR lines; expected all of the first and none of the second:"
    scan "$scratch"
    exit 1
  fi
  echo "AMRAPICheck self-test: all $seeded seeded AMR calls reported, no non-AMR line"
  exit 0
fi

root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
hits="$(scan "$root")"
if [ -n "$hits" ]; then
  echo "$hits"
  echo "AMRAPICheck: $(echo "$hits" | wc -l) AMR API call(s) above are outside the compatibility" \
    "layer; call the amrdm_vtk::amrcompat functions of Mapper/AMRDualMeshVTKCompat.h instead"
  exit 1
fi
echo "AMRAPICheck: every AMR API call in Mapper/ and Plugin/ goes through Mapper/AMRDualMeshVTKCompat"
exit 0
