"""Opens EDEM's field output in ParaView (pvpython, Debian's paraview package) as a user would:
the XDMF index, Warp By Vector on the zones' displacement, and checks that the crown's gridpoint
lands where EDEM says it is now, that the state and material legends are in the index, and that no
point is left unreferenced. Usage: pvpython paraview_check.py DIR (where scene.lua ran)."""
import sys
import xml.etree.ElementTree as ET

from paraview import servermanager
from paraview.simple import OpenDataFile, WarpByVector
from paraview.vtk.numpy_interface import dataset_adapter as dsa
import numpy as np

from expected import Checks, read_expected

directory = sys.argv[1]
expected = read_expected(directory)
check = Checks()
failures = check.failures


reader = OpenDataFile(f"{directory}/stages.xdmf")
last = reader.TimestepValues[-1] if reader.TimestepValues else 0.0
check("last time step", last, expected["cycle"])
warp = WarpByVector(Input=reader)
warp.Vectors = ["POINTS", "displacement"]
warp.ScaleFactor = 1.0
warp.UpdatePipeline(last)


def grids_of(data):
    """The frame's grids: the leaves of the composite the reader gives (zones, contacts, ...)."""
    leaves = []
    if data.IsA("vtkMultiBlockDataSet"):
        for i in range(data.GetNumberOfBlocks()):
            leaves += grids_of(data.GetBlock(i))
    elif data.IsA("vtkMultiPieceDataSet"):
        for i in range(data.GetNumberOfPieces()):
            leaves += grids_of(data.GetPiece(i))
    elif data is not None:
        leaves.append(data)
    return leaves


# The zones: the grid with stresses per cell.
grids = [dsa.WrapDataObject(g) for g in grids_of(servermanager.Fetch(warp))]
print("grids in the last frame:", [(g.GetNumberOfPoints(), g.GetNumberOfCells()) for g in grids])
zones = next(g for g in grids if "sxx" in g.CellData.keys())
points = np.array(zones.Points)[:, :2]
displacement = np.array(zones.PointData["displacement"])
reference = points - displacement[:, :2]
crown = int(np.argmin(np.hypot(reference[:, 0] - expected["crown_x"], reference[:, 1] - expected["crown_y"])))
check("crown: reference y [m]", reference[crown, 1], expected["crown_y"], 1e-12)
check("crown: warped x [m]", points[crown, 0], expected["crown_x"] + expected["crown_ux"], 1e-12)
check("crown: warped y [m]", points[crown, 1], expected["crown_y"] + expected["crown_uy"], 1e-12)
check("zone points, all referenced", points.shape[0], expected["zones_gridpoints"])
check("zone cells", zones.GetNumberOfCells(), expected["zones"])
for name in ("state", "material"):
    check(f"cell array {name}", int(name in zones.CellData.keys()), 1)
frame = ET.parse(f"{directory}/stages.xdmf").getroot().find("Domain/Grid").findall("Grid")[-1]
legends = {a.get("Name"): a.find("Information").get("Value") for a in frame.find("Grid[@Name='zones']").iter("Attribute")
           if a.find("Information") is not None}
print("legends:", legends)
check("material legend names rock and intact", int(legends.get("material") == "0 rock, 1 intact"), 1)
check("state legend", int(legends.get("state", "").startswith("bits: 1 shear now")), 1)
if failures:
    print("FAILED:", "; ".join(failures))
    sys.exit(1)
print("ParaView reads the field output: all checks hold")
