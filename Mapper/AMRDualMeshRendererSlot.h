// The renderer slot of vtkAMRDualMeshVolumeMapper: the kernel renderer created for the mapper's
// Device, and what was uploaded into it (the dual mesh, the region's proxy, the transfer function
// with its majorants), each with its own time stamp. The accumulation restarts when the slot
// changed after it started (GetChangeTime(), part of the reset key). Errors are reported as the
// owning mapper's (vtkErrorWithObjectMacro), each said once where it could repeat. Not wrapped.
#pragma once

#include "vtkTimeStamp.h"
#include "vtkType.h"

#include "render/Renderer.h"

#include <memory>
#include <string>

class AMRDualMeshInputSlot;
class vtkAMRDualMesh;
class vtkAMRDualMeshVolumeMapper;
class vtkObject;
class vtkVolumeProperty;
namespace amrdm_vtk
{
class RegionClip;
}

class AMRDualMeshRendererSlot
{
public:
  /// What the uploads are made with (the mapper's parameters).
  struct Settings
  {
    int Device = 0;                  ///< vtkAMRDualMeshVolumeMapper::Devices
    const char* DeviceName = "AUTO"; ///< for messages
    int MajorantResolution = 0;
    int Threads = 1;
  };

  /// `owner` reports the errors (the mapper).
  explicit AMRDualMeshRendererSlot(vtkObject* owner)
    : Owner(owner)
  {
  }

  /// Creates the renderer when there is none or Device changed, uploads `mesh` when it was
  /// rebuilt and the region's proxy (`proxyMesh`'s dual mesh, null for none) when it or the
  /// region changed. False (after an error) when there is no renderer to draw with.
  bool UpdateRenderer(const Settings& settings,
    vtkAMRDualMesh* mesh,
    vtkAMRDualMesh* proxyMesh,
    const amrdm::DualMesh* proxy,
    const amrdm_vtk::RegionClip& region);

  /// Samples `property`'s transfer function and sets it (and so the majorants) on the renderer
  /// when its functions or unit distance changed. False after an error.
  bool UpdateTransferFunction(const Settings& settings, vtkVolumeProperty* property);

  /// Both of the above with `mapper`'s Device, MajorantResolution and threads, for `input`'s
  /// meshes (the proxy's only with `region` active) and `property`.
  bool Update(vtkAMRDualMeshVolumeMapper* mapper,
    const AMRDualMeshInputSlot& input,
    const amrdm_vtk::RegionClip& region,
    vtkVolumeProperty* property);

  /// The device the renderer runs on (vtkAMRDualMeshVolumeMapper::Devices), -1 without one.
  int GetRenderingDevice() const;
  /// Host bytes the renderer keeps on top of the dual mesh, 0 without one.
  vtkTypeUInt64 GetAccelerationBytes() const;

  /// Forgets the mesh in the renderer (its build failed): the next UpdateRenderer() uploads.
  void ForgetMesh() { this->MeshInRenderer = nullptr; }

  amrdm::Renderer* GetRenderer() const { return this->Renderer.get(); }
  const amrdm::DualMesh* GetMesh() const { return this->MeshInRenderer; }
  bool GetProxyAccepted() const { return this->ProxyAccepted; }
  const std::string& GetDeviceReport() const { return this->DeviceReport; }

  /// The last change of what the renderer holds (renderer, mesh, proxy, transfer function).
  vtkMTimeType GetChangeTime() const { return this->ChangeTime.GetMTime(); }

  vtkTimeStamp UploadTime;           ///< when the dual mesh was last given to the renderer
  vtkTimeStamp TransferFunctionTime; ///< when the transfer function was last checked

private:
  vtkObject* Owner;
  std::unique_ptr<amrdm::Renderer> Renderer; ///< created for Device by UpdateRenderer()
  int RendererDevice = -1;                   ///< the Device it was created for
  std::string DeviceError;                   ///< why the last creation failed (said once)
  std::string DeviceReport;                  ///< the factory's last line (device chosen, why)
  const amrdm::DualMesh* MeshInRenderer = nullptr;
  vtkMTimeType MeshBuildTime = 0;

  const amrdm::DualMesh* ProxyInRenderer = nullptr; ///< the proxy last given to the renderer
  bool ProxyAccepted = false;                       ///< ... and the renderer took it
  vtkMTimeType ProxyBuildTime = 0;
  double ProxyBox[6] = { 0, 0, 0, 0, 0, 0 }; ///< the region it was given to the renderer for
  std::string ProxyError;                    ///< why the renderer refused it (said once)

  // Transfer function currently in the renderer, and what it was sampled from.
  amrdm::TransferFunction Tf;
  bool HasTf = false;
  vtkVolumeProperty* TfProperty = nullptr;
  const void* TfFunctions[2] = { nullptr, nullptr };
  std::string TfWarning; ///< the last transfer-function warning (said once)

  vtkTimeStamp ChangeTime; ///< see GetChangeTime()
};
