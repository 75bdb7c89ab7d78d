#!/usr/bin/env bash
# Layers run one way: Kernels <- Mapper <- Plugin. Fails if a lower layer includes a higher one.
set -u
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
status=0
# Kernels: C++17 + GLM only; no VTK, no ParaView, nothing from Mapper or Plugin.
if grep -rnE '#\s*include\s*[<"](vtk|pq|vtkPV|vtkSM)[A-Za-z0-9_]*\.h' "$root/Kernels"; then
  echo "LayerCheck: Kernels/ includes VTK or ParaView headers (above)"; status=1
fi
if grep -rnE '#\s*include\s*[<"].*(Mapper|Plugin)/' "$root/Kernels"; then
  echo "LayerCheck: Kernels/ includes Mapper/ or Plugin/ (above)"; status=1
fi
if grep -rnE 'find_package\((VTK|ParaView)|VTK::|ParaView::' "$root/Kernels"; then
  echo "LayerCheck: Kernels/ CMake links VTK or ParaView (above)"; status=1
fi
# Tools/ (amrdm-devcheck): kernels only, like Kernels/: it must build without VTK or ParaView.
if [ -d "$root/Tools" ] && grep -rnE '#\s*include\s*[<"](vtk|pq|vtkPV|vtkSM)[A-Za-z0-9_]*\.h|#\s*include\s*[<"].*(Mapper|Plugin|Apps)/|find_package\((VTK|ParaView)|VTK::|ParaView::' "$root/Tools"; then
  echo "LayerCheck: Tools/ uses VTK, ParaView, Mapper/, Plugin/ or Apps/ (above)"; status=1
fi
# Mapper: no ParaView server-manager or plugin code (vtkPV*, vtkSM*, pq*; no exception for
# vtkSMP*: Mapper/ does not use it, so the rule needs none).
if [ -d "$root/Mapper" ] && grep -rnE '#\s*include\s*[<"](vtkPV|vtkSM|pq)[A-Za-z0-9_]*\.h|Plugin/' "$root/Mapper"; then
  echo "LayerCheck: Mapper/ includes ParaView or Plugin/ headers (above)"; status=1
fi
# Mapper: VTK's public headers only (not its private SMP/ backend implementation).
if [ -d "$root/Mapper" ] && grep -rnE '#\s*include\s*[<"]SMP/' "$root/Mapper"; then
  echo "LayerCheck: Mapper/ includes VTK's private SMP/ headers (above)"; status=1
fi
[ $status -eq 0 ] && echo "LayerCheck: Kernels <- Mapper <- Plugin holds; Tools/ is kernels only"
exit $status
