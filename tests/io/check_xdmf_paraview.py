"""Opens particles.xmf and fields.xmf with ParaView's XDMF reader, as a user
would, and checks what ParaView sees at every time step: the grains as
N points with the arrays radius, velocity (3 components), glued and
trajectory_id; the fluid as NX * NY * NZ cells with its fields and the
fluid_velocity vector; the time steps of the files.

The reader is ParaView's "XDMF Reader" (XDMF 2): the Xdmf3 readers of
ParaView 5.11 skip HyperSlab selections ("Skipping unrecognized array type").

usage: pvpython check_xdmf_paraview.py DIR N NT NX NY NZ
"""
import sys

from paraview import servermanager
from paraview.simple import XDMFReader, UpdatePipeline

directory, n, nt, nx, ny, nz = sys.argv[1], *map(int, sys.argv[2:7])
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def leaf(data):
    """The first dataset of a possibly multiblock output."""
    if data.IsA("vtkMultiBlockDataSet"):
        it = data.NewIterator()
        it.InitTraversal()
        return it.GetCurrentDataObject() if not it.IsDoneWithTraversal() else None
    return data


def read(name):
    reader = XDMFReader(FileNames=[f"{directory}/{name}"])
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else []
    check(len(times) == nt, f"{name}: {len(times)} time steps, expected {nt}")
    frames = []
    for t in times:
        UpdatePipeline(time=t, proxy=reader)
        frames.append(leaf(servermanager.Fetch(reader)))
    return frames


for k, grains in enumerate(read("particles.xmf")):
    check(grains is not None and grains.GetNumberOfPoints() == n,
          f"particles step {k}: {grains.GetNumberOfPoints() if grains else None} points, expected {n}")
    pd = grains.GetPointData()
    for array, comps in (("radius", 1), ("velocity", 3), ("glued", 1), ("trajectory_id", 1)):
        a = pd.GetArray(array)
        check(a is not None and a.GetNumberOfComponents() == comps and a.GetNumberOfTuples() == n,
              f"particles step {k}: point array {array} ({comps} components)")
    bounds = grains.GetBounds()
    check(bounds[0] < bounds[1], f"particles step {k}: bounds {bounds}")

for k, fluid in enumerate(read("fields.xmf")):
    check(fluid is not None and fluid.GetNumberOfCells() == nx * ny * nz,
          f"fields step {k}: {fluid.GetNumberOfCells() if fluid else None} cells, expected {nx * ny * nz}")
    dims = fluid.GetDimensions() if hasattr(fluid, "GetDimensions") else None
    check(dims is not None and tuple(dims) == (nx + 1, ny + 1, nz + 1), f"fields step {k}: dims {dims}")
    cd = fluid.GetCellData()
    for array, comps in (("fluid_fraction", 1), ("u_fluid", 1), ("excess_pressure", 1), ("fluid_velocity", 3)):
        a = cd.GetArray(array)
        check(a is not None and a.GetNumberOfComponents() == comps and a.GetNumberOfTuples() == nx * ny * nz,
              f"fields step {k}: cell array {array} ({comps} components)")
    vel = cd.GetArray("fluid_velocity")
    for c, comp in enumerate(("u_fluid", "v_fluid", "w_fluid")):
        a = cd.GetArray(comp)
        same = vel is not None and a is not None and all(
            vel.GetComponent(i, c) == a.GetValue(i) for i in range(a.GetNumberOfTuples()))
        check(same, f"fields step {k}: fluid_velocity component {c} is {comp}")

for f in failures:
    print("FAIL", f)
print("paraview: %d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
