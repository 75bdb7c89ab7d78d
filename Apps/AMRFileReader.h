// Opens any AMR file VTK reads as a vtkOverlappingAMR with every level and every cell array:
// Enzo (.hierarchy / .boundary), AMReX plotfile folders (with a Header file), and XML .vthb.
#ifndef AMRFileReader_h
#define AMRFileReader_h

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string>

class vtkOverlappingAMR;

namespace amrdm_app
{
/// Returns null and sets `error` when the path is not a supported AMR file.
vtkSmartPointer<vtkOverlappingAMR> ReadAMRFile(const std::string& path, std::string& error);
}

#endif
