"""AMR dual-mesh volume rendering for VTK: `from amrdualmesh import vtkAMRDualMesh`."""
from .AMRDualMeshMapper import *  # noqa: F401,F403
