#!/usr/bin/env python3
"""Checkpoints whose datasets disagree in size, with a valid checksum, never crash edem.

A bolted model is saved; then, one dataset at a time (those whose path starts with PREFIX), the
dataset is cut to its first element, or emptied, and the header's length and CRC-32 recomputed,
so that only the reader's own checks stand between the file and the model. Each file is
restored and cycled once: edem must load it and cycle (status 0) or refuse it with a message
naming the file (status 1), never crash or hang.

    python3 checkpoint_datasets.py EDEM WORKDIR [PREFIX]

SHOW_LOADED=1 lists the files that loaded (a cut the reader cannot tell from a valid file).
"""
import os
import shutil
import subprocess
import sys
import zlib

import h5py

MODEL = """
block{ x = {0, 4}, y = {0, 2} }
crack{ from = {0.5, 2.5}, to = {3.5, -0.5} }
region{ name = "right", polygon = {{3, 0}, {4, 0}, {4, 2}, {1, 2}} }
zone{ edge = 0.25 }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "joint", kn = 5e9, ks = 5e9, friction = 25 }
jassign{ material = "joint" }
gravity{ 0, -9.81 }
boundary{ side = "left", fix = "xy" }
bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, failure_strain = 0.035,
               bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
bolt{ from = {0.5, 0.8}, to = {3.5, 1.4}, segments = 24, material = "rebar" }
cycle(20)
save("good.h5")
"""
HEADER = 512


def reseal(path):
    """The header's byte count and CRC-32 made to match the file as it now is."""
    with open(path, "rb") as f:
        data = f.read()
    head = data[:HEADER].rstrip(b"\0").decode()
    lines = [l for l in head.split("\n") if l and not l.startswith("bytes") and not l.startswith("crc32")]
    body = "\n".join(lines) + "\n" + f"bytes {len(data)}\n"
    crc = zlib.crc32(data[HEADER:], zlib.crc32(body.encode()))
    header = (body + f"crc32 {crc:08x}\n").encode().ljust(HEADER, b"\0")
    with open(path, "wb") as f:
        f.write(header + data[HEADER:])


def start_work(edem, work, load):
    """In `work` (made, and made the current folder): good.h5 saved from MODEL, and load.lua with
    the script `load` that restores a damaged copy."""
    os.makedirs(work, exist_ok=True)
    os.chdir(work)
    with open("make.lua", "w") as f:
        f.write(MODEL)
    subprocess.run([edem, "-q", "make.lua"], check=True)
    with open("load.lua", "w") as f:
        f.write(load)


def datasets(path, prefix):
    found = []
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: found.append(name)
                     if isinstance(obj, h5py.Dataset) and name.startswith(prefix) and obj.shape
                     and obj.shape[0] > 1 else None)
    return found


def cut(source, target, name, keep):
    shutil.copyfile(source, target)
    with h5py.File(target, "r+") as f:
        data = f[name][:keep]
        attributes = dict(f[name].attrs)
        del f[name]
        f.create_dataset(name, data=data)
        for k, v in attributes.items():
            f[name].attrs[k] = v
    reseal(target)


def main():
    edem, work = os.path.abspath(sys.argv[1]), sys.argv[2]
    prefix = sys.argv[3] if len(sys.argv) > 3 else ""
    start_work(edem, work, 'restore("cut.h5")\ncycle(1)\n')
    names = datasets("good.h5", prefix)
    assert names, f"no datasets under {prefix!r}"
    bad, loaded, refused = [], 0, 0
    for name in names:
        for keep in (1, 0):
            cut("good.h5", "cut.h5", name, keep)
            try:
                r = subprocess.run([edem, "-q", "--threads", "1", "load.lua"], capture_output=True, text=True,
                                   timeout=60)
            except subprocess.TimeoutExpired:
                bad.append(f"{name} cut to {keep}: hung")
                continue
            if r.returncode == 0:
                loaded += 1
                if os.environ.get("SHOW_LOADED"):
                    print(f"  loaded: {name} cut to {keep}")
            elif r.returncode == 1 and "load.lua:1: restore: " in r.stderr and "'cut.h5'" in r.stderr:
                refused += 1
            else:
                bad.append(f"{name} cut to {keep}: status {r.returncode}: {r.stderr.strip()[-300:]}")
    print(f"checkpoint_datasets: {len(names)} datasets, each cut to one element and emptied: "
          f"{refused} refused naming the file, {loaded} loaded and cycled, {len(bad)} otherwise")
    for b in bad:
        print("  " + b)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
