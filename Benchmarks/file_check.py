"""vtkAMRDualMeshFileCheck before a VTK or ParaView reader opens a file (issue 33): a damaged or
incomplete Enzo, AMReX or .vthb file stops the script with the check's one-line message (the
file and the problem) instead of a hang, a crash or a partial hierarchy. Works under python3 and
pvpython; the amrdualmesh package comes from PYTHONPATH or, failing that, from the build folder
(AMRDM_BUILD_DIR, default build/ next to Benchmarks/)."""
import os
import sys


def check_file(path):
    try:
        from amrdualmesh import vtkAMRDualMeshFileCheck
    except ImportError:
        build = os.environ.get("AMRDM_BUILD_DIR",
                               os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build"))
        sys.path.insert(0, os.path.join(build, "lib", "python3", "dist-packages"))
        from amrdualmesh import vtkAMRDualMeshFileCheck
    problem = vtkAMRDualMeshFileCheck.Check(path)
    if isinstance(problem, bytes):  # a damaged name that is not UTF-8
        problem = problem.decode("utf-8", "replace")
    if problem:
        raise RuntimeError(problem)
