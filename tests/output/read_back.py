"""Reads EDEM's field output back with h5py (Debian's python3-h5py) and the XDMF index with the
standard library, independently of EDEM: every DataItem the index names exists with the stated
dimensions, and the last frame holds the counts and values the script wrote to expected.txt.
Usage: read_back.py DIR (where scene.lua ran). Exit status 0 when all holds."""
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

from expected import Checks, read_expected

directory = sys.argv[1]
expected = read_expected(directory)
check = Checks()
failures = check.failures


def read_index(name):
    root = ET.parse(f"{directory}/{name}").getroot()
    series = root.find("Domain/Grid")
    assert series.get("CollectionType") == "Temporal"
    frames = series.findall("Grid")
    with h5py.File(f"{directory}/{name.rsplit('.', 1)[0]}.h5", "r") as data:
        for frame in frames:
            for item in frame.iter("DataItem"):
                file, path = item.text.split(":")
                dims = tuple(int(d) for d in item.get("Dimensions").split())
                if data[path].shape != dims:
                    failures.append(f"{name} {path}: shape {data[path].shape}, index says {dims}")
    return frames


frames = read_index("stages.xdmf")
check("stage frames", len(frames), expected["frames"])
check("frames every 400 cycles", len(read_index("every.xdmf")), expected["every_frames"])
last = frames[-1]
grids = {g.get("Name"): g for g in last.findall("Grid")}
check("last frame time", float(last.find("Time").get("Value")), expected["cycle"])
with h5py.File(f"{directory}/stages.h5", "r") as data:
    f = data[f"/frames/{len(frames)}"]
    check("cycle", int(f.attrs["cycle"]), expected["cycle"])
    check("stage", int(f.attrs["stage"]), expected["stage"])
    zones = f["zones"]
    check("zone cells", zones["cells"].shape[0], expected["zones"])
    check("zone cell attribute in the index", int(grids["zones"].find("Topology").get("NumberOfElements")),
          expected["zones"])
    points = zones["points"][:]
    check("points: the zones' in place, none else", points.shape[0], expected["zones_gridpoints"])
    check("first zone in place: sxx [Pa]", zones["sxx"][0], expected["zone_first_sxx"])
    check("last zone in place: s1 [Pa]", zones["s1"][-1], expected["zone_last_s1"])
    cells = zones["cells"][:]
    check("zone corners in range", int(cells.min() >= 0 and cells.max() < points.shape[0]), 1)
    check("every point a zone's corner", len(set(cells.flatten().tolist())), points.shape[0])
    # Points are where the gridpoints were made: Warp By Vector (points + displacement) puts
    # them where they are now.
    crown = int(np.argmin(np.hypot(points[:, 0] - expected["crown_x"], points[:, 1] - expected["crown_y"])))
    check("crown: reference x [m]", points[crown, 0], expected["crown_x"])
    check("crown: reference y [m]", points[crown, 1], expected["crown_y"])
    check("crown: uy [m]", zones["displacement"][crown, 1], expected["crown_uy"])
    check("crown: warped y [m]", points[crown, 1] + zones["displacement"][crown, 1],
          expected["crown_y"] + expected["crown_uy"], 1e-15)
    legend = zones.attrs["material_legend"]
    legend = legend.decode() if isinstance(legend, bytes) else legend
    check("material names in the file", len(legend.split(", ")), expected["materials"])
    check("material 0 is rock", int(legend.startswith("0 rock")), 1)
    index_legends = [i.get("Value") for i in grids["zones"].iter("Information")]
    check("legends in the index (state, material)", len(index_legends), 2)
    contacts = f["contacts"]
    check("contact cells", contacts["cells"].shape[0], expected["contacts"])
    check("contact fn sum [N/m]", float(np.sum(contacts["fn"][:])), expected["contact_fn_sum"], 1e-12)
    check("slipping contacts", int(np.sum(contacts["state"][:] == 2)), expected["contact_slipping"])
    cracks = f["cracks"]
    check("crack cells", cracks["cells"].shape[0], expected["cracks"])
    check("shear cracks", int(np.sum(cracks["mode"][:] == 1)), expected["cracks_shear"])
    for group in ("contacts", "cracks", "bolts"):
        check(f"{group}: a displacement per point", f[group]["displacement"].shape[0], f[group]["points"].shape[0])
    bolts = f["bolts"]
    check("bolt segment cells", bolts["cells"].shape[0], expected["bolt_segments"])
    check("largest bolt force [N/m]", float(np.max(bolts["force"][:])), expected["bolt_force_max"])
if failures:
    print("FAILED:", "; ".join(failures))
    sys.exit(1)
print("field output read back: all checks hold")
