"""The thread count of vtkAMRDualMeshVolumeMapper and vtkAMRDualMesh when NumberOfThreads is 0
(vtkAMRDualMesh::ResolveNumberOfThreads): VTK_SMP_MAX_THREADS when set, else all cores:
- VTK's default backend (Sequential in Debian's 9.2, STDThread in scripts/check-vtk-latest.sh's
  VTK 9.7; a VTK build option the count does not follow): all cores, VTK_SMP_MAX_THREADS=1
  gives 1; an explicit NumberOfThreads wins; PrintSelf says the count used;
- a dual-mesh build uses that count: after a build with NumberOfThreads 1 the process has no
  new threads (the pool started no worker); after one with the default it has cores - 1 more
  (the pool's workers, kept for the next build: a rebuild adds none);
- the STDThread backend with Initialize(1) changes nothing (the Mapper layer does not call
  vtkSMPTools, .ci/check-layers.sh).
Skips (exit 125) on a one-core machine, where 1 and "all cores" cannot be told apart."""
import os
import subprocess
import sys

from vtkmodules.vtkCommonCore import vtkSMPTools
from amrdualmesh import vtkAMRDualMesh, vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import checker, read_enzo  # noqa: E402

failures = []
check = checker(failures)


def threads_now():
    return len(os.listdir("/proc/self/task"))


cores = os.cpu_count() or 1
if cores < 2:
    print("skipped: one core, so 1 thread and the default (all cores) cannot be told apart")
    sys.exit(125)
if os.environ.get("VTK_SMP_MAX_THREADS") or os.environ.get("VTK_SMP_BACKEND_IN_USE"):
    print("skipped: VTK_SMP_MAX_THREADS or VTK_SMP_BACKEND_IN_USE is set in the environment")
    sys.exit(125)

mapper = vtkAMRDualMeshVolumeMapper()
mesh = vtkAMRDualMesh()
print("note: VTK's default SMP backend is %s" % vtkSMPTools.GetBackend())

# 1. VTK's default backend.
check(mapper.GetNumberOfThreads() == 0, "NumberOfThreads defaults to 0")
check(mapper.GetEffectiveNumberOfThreads() == cores,
      "default: all %d cores (mapper uses %d)" % (cores, mapper.GetEffectiveNumberOfThreads()))
check("NumberOfThreads: 0\n" in str(mapper) and "EffectiveNumberOfThreads: %d\n" % cores in str(mapper),
      "PrintSelf says the count used")
mapper.SetNumberOfThreads(3)
check(mapper.GetEffectiveNumberOfThreads() == 3, "an explicit NumberOfThreads (3) wins over vtkSMPTools")
check("NumberOfThreads: 3\n" in str(mapper) and "EffectiveNumberOfThreads: 3\n" in str(mapper),
      "PrintSelf says the explicit count")
mapper.SetNumberOfThreads(0)
env = dict(os.environ, VTK_SMP_MAX_THREADS="1")
code = "from amrdualmesh import vtkAMRDualMeshVolumeMapper as M; print(M().GetEffectiveNumberOfThreads())"
r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
check(r.returncode == 0 and r.stdout.strip() == "1",
      "VTK_SMP_MAX_THREADS=1: %s %s" % (r.stdout.strip(), r.stderr.strip()[-200:]))

# 2. A build uses the count: no pool worker with 1 thread, cores - 1 kept with the default.
amr = read_enzo()
mesh.SetInputData(amr)
mesh.SetArrayName("Density")
mesh.SetNumberOfThreads(1)
before = threads_now()
check(mesh.Update(), "the Enzo set builds with one thread")
serial = mesh.GetNumberOfHexes()
check(threads_now() == before, "a build with 1 thread starts no thread (%d -> %d)" % (before, threads_now()))
mesh.SetNumberOfThreads(0)
mesh.SetGridletSize(4)  # a rebuild
check(mesh.Update(), "the Enzo set builds with all cores")
check(threads_now() == before + cores - 1,
      "a build with the default starts the pool's %d worker(s) (%d -> %d threads)"
      % (cores - 1, before, threads_now()))
mesh.SetGridletSize(8)
check(mesh.Update() and mesh.GetNumberOfHexes() == serial, "the same mesh with 1 and %d threads" % cores)
check(threads_now() == before + cores - 1, "the next build reuses the workers (%d threads)" % threads_now())

# 3. The STDThread backend changes nothing: the Mapper layer does not follow vtkSMPTools.
if vtkSMPTools.SetBackend("STDThread"):
    vtkSMPTools.Initialize(1)
    check(mapper.GetEffectiveNumberOfThreads() == cores,
          "STDThread, Initialize(1): still all %d cores (%d)" % (cores, mapper.GetEffectiveNumberOfThreads()))
    vtkSMPTools.Initialize()
    vtkSMPTools.SetBackend("Sequential")
else:
    print("note: this VTK has no STDThread backend; its case is not checked")

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
