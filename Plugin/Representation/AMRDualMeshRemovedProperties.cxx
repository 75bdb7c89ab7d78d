#include "AMRDualMeshRemovedProperties.h"

#include "vtkObject.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <mutex>

void AMRDualMeshRemovedProperties::Report(vtkObject* reporter, vtkVolumeProperty* property) const
{
  const double unit = property->GetScalarOpacityUnitDistance();
  const double old = this->UnitDistance;
  if (old > 0.0 && std::abs(old - unit) > 1e-6 * std::max(std::abs(old), std::abs(unit)))
  {
    static std::once_flag said;
    std::call_once(said,
      [&]
      {
        vtkWarningWithObjectMacro(reporter,
          "PathTracerScalarOpacityUnitDistance was removed: the representation "
          "uses ScalarOpacityUnitDistance (the Volume representation's), now "
            << unit << "; the value " << old
            << " of the old name is not used. Set ScalarOpacityUnitDistance = " << old
            << " for the old picture.");
      });
  }
  if (this->Shade >= 0 && (this->Shade != 0) != (property->GetShade() != 0))
  {
    static std::once_flag said;
    std::call_once(said,
      [&]
      {
        vtkWarningWithObjectMacro(reporter,
          "PathTracerShade was removed: the representation uses Shade (the "
          "Volume representation's), now "
            << property->GetShade() << "; the value " << this->Shade
            << " of the old name is not used. Set Shade = " << this->Shade
            << " for the old picture.");
      });
  }
}
