// The input slot of vtkAMRDualMeshVolumeMapper: the vtkOverlappingAMR on its input port (checked
// and updated), the array chosen the VTK way (AMRDualMeshArraySelection.h: point or cell data),
// and the dual mesh it owns (vtkAMRDualMesh::BuildTime follows the input, the array and the build
// parameters); with a region, also the region's proxy and its own dual mesh (same array and
// parameters). The mesh's progress is forwarded to the mapper; errors are the mapper's
// (vtkErrorWithObjectMacro). Not wrapped.
#pragma once

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <ostream>
#include <string>

class vtkAMRDualMesh;
class vtkAMRDualMeshVolumeMapper;
class vtkCallbackCommand;
class vtkIndent;
class vtkObject;
class vtkOverlappingAMR;
namespace amrdm
{
struct DualMesh;
}
namespace amrdm_vtk
{
class RegionClip;
}

class AMRDualMeshInputSlot
{
public:
  /// `owner` has the input port, chooses the array and the build parameters (its ScalarMode,
  /// SelectScalarArray, GridletSize, BVHLeafSize, NumberOfThreads), receives the progress and
  /// reports the errors.
  explicit AMRDualMeshInputSlot(vtkAMRDualMeshVolumeMapper* owner);
  ~AMRDualMeshInputSlot();

  /// The input after its producer's update; null (quietly) without one or for another type.
  vtkOverlappingAMR* UpdateAndGetInput();
  /// UpdateAndGetInput() with an error saying what is missing or wrong.
  vtkOverlappingAMR* CheckInput();
  /// What the mapper draws (vtkAbstractMapper3D::GetBounds): the active region's box, else the
  /// input's bounds, uninitialised (vtkMath::UninitializeBounds) without input or cells.
  void GetBounds(const amrdm_vtk::RegionClip& region, double bounds[6]);
  /// Chooses the array of `amr` and brings the dual mesh (and, with `region` active, the proxy's)
  /// up to date. False after an error (empty input, no array, a failed build: `meshLost` true,
  /// the renderer must forget the mesh).
  bool Update(vtkOverlappingAMR* amr, const amrdm_vtk::RegionClip& region, bool& meshLost);

  /// Sets the region's proxy (null: none); returns whether it changed.
  bool SetProxy(vtkOverlappingAMR* proxy);
  /// The proxy's dual mesh the renderer should hold: null without a proxy, region or build.
  const amrdm::DualMesh* GetProxyToRender(const amrdm_vtk::RegionClip& region) const;

  vtkAMRDualMesh* GetMesh() const { return this->Mesh; }
  vtkAMRDualMesh* GetProxyMesh() const { return this->ProxyMesh; }

  /// PrintSelf's RegionIndex and RegionProxy lines (`proxyAccepted`: the renderer took it).
  void PrintRegion(std::ostream& os,
    vtkIndent indent,
    const amrdm_vtk::RegionClip& region,
    bool proxyAccepted) const;

private:
  /// Sets `mesh`'s input, array, association (the input mesh's) and build parameters, updates it.
  bool Build(vtkAMRDualMesh* mesh, vtkOverlappingAMR* amr, const std::string& array);
  static void ForwardProgress(vtkObject*, unsigned long, void* clientData, void* callData);
  static void CatchError(vtkObject*, unsigned long, void* clientData, void* callData);

  vtkAMRDualMeshVolumeMapper* Owner;
  vtkNew<vtkAMRDualMesh> Mesh;
  vtkSmartPointer<vtkOverlappingAMR> ProxyInput; ///< the region's proxy (SetRegionProxy)
  vtkNew<vtkAMRDualMesh> ProxyMesh;              ///< its dual mesh
  vtkNew<vtkCallbackCommand> ProgressForwarder;
  vtkNew<vtkCallbackCommand> ErrorCatcher;
  std::string MeshError; ///< last error reported by a dual mesh
};
