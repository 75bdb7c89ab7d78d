// Opens any AMR file VTK reads as a vtkOverlappingAMR with every level and every cell array:
// Enzo (.hierarchy / .boundary), AMReX plotfile folders (with a Header file), and XML .vthb.
//
// Guarded (issue 33): vtkAMRDualMeshFileCheck checks the files before the VTK reader sees them
// (a damaged file is a one-line error naming the file), and the reader's output is compared
// with the metadata (fewer blocks or missing arrays are an error, not a partial render). Where
// a third-party reader could still misbehave on damage the check cannot see (inside HDF5 data,
// say), two last guards end the process with a message naming the file, exit status 1: a
// watchdog when the reader has not returned after vtkAMRDualMeshFileCheck::GetReadTimeoutSeconds()
// (10 s + 1 s per 5 MB of data; AMRDM_READ_TIMEOUT=seconds overrides it), and a handler for a
// fatal signal (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) raised while the reader runs.
#ifndef AMRFileReader_h
#define AMRFileReader_h

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string>

class vtkOverlappingAMR;

namespace amrdm_app
{
/// Returns null and sets `error` (one line naming the file) when the path is not a supported,
/// whole AMR file. May end the process (status 1, a message on stderr) as described above.
vtkSmartPointer<vtkOverlappingAMR> ReadAMRFile(const std::string& path, std::string& error);
}

#endif
