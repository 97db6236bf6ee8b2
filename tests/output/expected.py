"""What scene.lua wrote to expected.txt (key = value), and a check that prints measured, expected
and the verdict, shared by read_back.py (h5py) and paraview_check.py (pvpython)."""


def read_expected(directory):
    expected = {}
    for line in open(f"{directory}/expected.txt"):
        key, value = line.split(" = ")
        expected[key] = float(value)
    return expected


class Checks:
    def __init__(self):
        self.failures = []

    def __call__(self, what, measured, wanted, tolerance=0.0):
        ok = abs(measured - wanted) <= tolerance * max(abs(wanted), 1.0)
        print(f"{what}: measured {measured!r}, expected {wanted!r}{'' if ok else '  FAIL'}")
        if not ok:
            self.failures.append(what)
