"""ParaView reads what mpm writes (issue 9 item 7), checked with ParaView's own readers.

Run by pvpython (Debian python3-paraview) from CTest (label "paraview"):
    pvpython check_paraview_outputs.py MPM_BINARY DECK_DIR SCRATCH_DIR
It copies the CB-Geo Mohr-Coulomb GIMP column deck (tests/data/reference_runs/cbgeo/mc_column_gimp_short),
asks for CB-Geo's VTK output (post_processing.vtk / vtk_statevars), runs mpm for 500 steps and loads
particles.xdmf, particles.pvd and grid.vtr. Expected values come from the deck's own files: the
first frame is the start state, so its stresses are particles-stresses.txt; sizes follow from nsize
(= 2/ppd, CB-Geo's default for 4x4 particles per 0.5 m cell) and the cell size.
"""
import json
import math
import shutil
import subprocess
import sys
from pathlib import Path

from paraview import servermanager
from paraview.simple import OpenDataFile
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_DOUBLE, VTK_LONG, VTK_LONG_LONG, VTK_ID_TYPE

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def fetch(source, time):
    # source.UpdatePipeline(t), not simple.UpdatePipeline(time=t): the latter ignores t = 0.0.
    source.UpdatePipeline(time)
    data = servermanager.Fetch(source)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    return data


def array(data, name):
    a = data.GetPointData().GetArray(name)
    check(a is not None, f"array {name} present")
    return a


def main():
    mpm, deck_dir, scratch = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    shutil.rmtree(scratch, ignore_errors=True)
    shutil.copytree(deck_dir, scratch)
    shutil.rmtree(scratch / "results", ignore_errors=True)
    deck = json.loads((scratch / "mpm.json").read_text())
    deck["analysis"]["nsteps"] = 501
    deck["post_processing"]["vtk"] = ["stresses", "strains", "velocities", "displacements"]
    deck["post_processing"]["vtk_statevars"] = [{"phase_id": 0, "statevars": ["pdstrain"]}]
    (scratch / "mpm.json").write_text(json.dumps(deck, indent=1))
    subprocess.run([str(mpm), "-f", str(scratch) + "/", "-i", "mpm.json"], check=True)
    out = scratch / "results" / deck["analysis"]["uuid"]

    stresses = [list(map(float, line.split())) for line in (scratch / "particles-stresses.txt").read_text().split("\n")[1:] if line.strip()]
    n = len(stresses)
    expected_times = [0.0] + [(s + 1) * deck["analysis"]["dt"] for s in range(0, 501, 250)]

    # XDMF: the temporal collection, the start state first.
    xdmf = OpenDataFile(str(out / "particles.xdmf"))
    times = list(xdmf.TimestepValues)
    check(len(times) == len(expected_times) and all(abs(a - b) < 1e-12 for a, b in zip(times, expected_times)),
          f"XDMF times {times} == {expected_times}")
    first = fetch(xdmf, times[0])
    check(first.GetNumberOfPoints() == n, f"{first.GetNumberOfPoints()} points == {n} particles")
    stress = array(first, "stress")
    check(stress.GetNumberOfComponents() == 6, "stress is a 6-component symmetric tensor")
    check(array(first, "strain").GetNumberOfComponents() == 6, "strain is a 6-component symmetric tensor")
    ids = array(first, "id")
    check(ids.GetDataType() in (VTK_LONG, VTK_LONG_LONG, VTK_ID_TYPE), f"id is an integer array (VTK type {ids.GetDataType()})")
    for name in ("material_id", "cell_id", "status"):
        check(array(first, name).GetDataType() != VTK_DOUBLE, f"{name} is an integer array")
    for name in ("friction", "cohesion", "pdstrain", "radius", "size"):
        array(first, name)
    s = vtk_to_numpy(stress)
    i = vtk_to_numpy(ids)
    # Particle ids are 0..n-1 in file order, so id k carries line k of the stress file
    # (FORMATS.md section 5: sxx syy szz sxy syz sxz); ParaView order xx yy zz xy yz xz.
    worst = max(abs(s[k][c] - stresses[int(i[k])][c]) for k in range(n) for c in range(4))
    check(worst <= 1e-6 * 139056.75, f"first-frame stress equals particles-stresses.txt (worst {worst} Pa)")
    friction = vtk_to_numpy(array(first, "friction"))
    phi = deck["materials"][0]["friction"]
    check(abs(friction.min() - phi) < 1e-9 and abs(friction.max() - phi) < 1e-9, f"friction = {phi} degrees everywhere")
    size = vtk_to_numpy(array(first, "size"))
    radius = vtk_to_numpy(array(first, "radius"))
    mesh_lines = (scratch / "mesh.txt").read_text().split("\n")
    x0, x1 = float(mesh_lines[1].split()[0]), float(mesh_lines[2].split()[0])
    h = abs(x1 - x0)
    volume = vtk_to_numpy(array(first, "volume"))
    check(abs(size[0][0] * size[0][1] - volume[0]) < 1e-9 * volume[0],
          f"particle size {size[0][:2]} covers its volume {volume[0]} (cell {h} m)")
    check(abs(radius[0] - 0.5 * math.sqrt(volume[0])) < 1e-12, "radius = half the side of the particle")
    last = fetch(xdmf, times[-1])
    check(vtk_to_numpy(array(last, "displacement")).std() > 0, "the last frame has moved")

    # VTK PolyData collection (post_processing.vtk honoured).
    pvd = OpenDataFile(str(out / "particles.pvd"))
    pvd_times = list(pvd.TimestepValues)
    check(len(pvd_times) == len(times) and all(abs(a - b) < 1e-12 for a, b in zip(pvd_times, times)),
          f"PVD times {pvd_times} == XDMF times")
    vtp = fetch(pvd, pvd_times[-1])
    for name in ("stress", "strain", "velocity", "displacement", "pdstrain", "id", "radius"):
        array(vtp, name)
    check(vtp.GetNumberOfPoints() == n and vtp.GetNumberOfVerts() == n, "PolyData: one vertex per particle")
    same = vtk_to_numpy(array(vtp, "stress"))
    xdmf_last = vtk_to_numpy(array(last, "stress"))
    check(abs(same - xdmf_last).max() == 0, "VTP and XDMF carry the same stresses")

    # Background grid with its boundary conditions.
    grid = fetch(OpenDataFile(str(out / "grid.vtr")), 0)
    nodes = int(mesh_lines[0].split()[0])
    check(grid.GetNumberOfPoints() == nodes, f"grid.vtr has {grid.GetNumberOfPoints()} nodes == {nodes} in mesh.txt")
    check(vtk_to_numpy(array(grid, "fixed_y")).sum() > 0 and vtk_to_numpy(array(grid, "friction")).max() == 0.5,
          "grid carries the velocity and friction constraints")

    print(f"{len(failures)} failed checks")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
