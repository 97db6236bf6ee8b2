#!/usr/bin/env python3
"""Randomly damaged checkpoints with a valid checksum never crash, hang or run away with memory.

The bolted model of checkpoint_datasets.py is saved; each mutant (seeded, reproducible) takes
one dataset and does one of: cut it to a random length, lengthen it with copies of its own
elements, set one element to an extreme value (NaN, infinity, -1, an index past any array, the
largest and smallest 32-bit integers, 1e300), or swap two elements. The header's length and
CRC-32 are recomputed, so that only the reader's own checks stand between the file and the
model. Each file is restored and cycled 5 times under 60 s and 2 GB of address space: it must
load and cycle (status 0), be refused naming the file (status 1), or load a state nothing in the
file contradicts (positions swapped, say) that cycling then stops with a message at its line.

    python3 checkpoint_mutants.py EDEM WORKDIR [MUTANTS] [SEED]
"""
import os
import random
import resource
import shutil
import subprocess
import sys

import h5py
import numpy

from checkpoint_datasets import reseal, start_work

TIME_LIMIT = 60  # s
MEMORY_LIMIT = 2 << 30  # bytes of address space


def all_datasets(path):
    found = []
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: found.append(name)
                     if isinstance(obj, h5py.Dataset) and obj.shape and obj.shape[0] > 0 else None)
    return found


def extreme(dtype, length, rng):
    if numpy.issubdtype(dtype, numpy.floating):
        return rng.choice([numpy.nan, numpy.inf, -numpy.inf, -1.0, 0.0, 1e300, -1e300])
    if numpy.issubdtype(dtype, numpy.integer):
        info = numpy.iinfo(dtype)
        return rng.choice([v for v in (-1, length, length + 1000, info.max, info.min, 0) if info.min <= v <= info.max])
    return None


def mutate(source, target, name, rng):
    """Applies one edit to dataset `name`; returns what it did."""
    shutil.copyfile(source, target)
    with h5py.File(target, "r+") as f:
        data = f[name][()]
        attributes = dict(f[name].attrs)
        n = data.shape[0]
        kind = rng.randrange(4)
        if kind == 0:
            keep = rng.randrange(n)
            data, what = data[:keep], f"cut to {keep}"
        elif kind == 1:
            extra = rng.randint(1, max(1, n))
            data, what = numpy.concatenate([data, data[:extra]]), f"lengthened by {extra}"
        elif kind == 2 and extreme(data.dtype, n, rng) is not None:
            at = rng.randrange(data.size)
            value = extreme(data.dtype, n, rng)
            flat = data.reshape(-1).copy()
            flat[at] = value
            data, what = flat.reshape(data.shape), f"element {at} set to {value}"
        elif n > 1:
            i, j = rng.randrange(n), rng.randrange(n)
            data = data.copy()
            data[[i, j]] = data[[j, i]]
            what = f"elements {i} and {j} swapped"
        else:
            data, what = data[:0], "emptied"
        del f[name]
        f.create_dataset(name, data=data)
        for k, v in attributes.items():
            f[name].attrs[k] = v
    reseal(target)
    return what


def limit_memory():
    # AddressSanitizer reserves terabytes of address space for its shadow memory and cannot start
    # under a limit: under it (the sanitizer build's suite) memory goes unbounded.
    if "ASAN_OPTIONS" not in os.environ:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def main():
    edem, work = os.path.abspath(sys.argv[1]), sys.argv[2]
    count = int(sys.argv[3]) if len(sys.argv) > 3 else 100
    rng = random.Random(int(sys.argv[4]) if len(sys.argv) > 4 else 1)
    start_work(edem, work, 'restore("mutant.h5")\ncycle(5)\n')
    names = all_datasets("good.h5")
    bad, loaded, refused, stopped = [], 0, 0, 0
    for k in range(count):
        name = rng.choice(names)
        what = mutate("good.h5", "mutant.h5", name, rng)
        try:
            r = subprocess.run([edem, "-q", "--threads", "1", "load.lua"], capture_output=True, text=True,
                               errors="replace", timeout=TIME_LIMIT, preexec_fn=limit_memory)
        except subprocess.TimeoutExpired:
            bad.append(f"mutant {k}: {name} {what}: hang (over {TIME_LIMIT} s)")
            continue
        first = r.stderr.split("\n", 1)[0]
        if r.returncode == 0:
            loaded += 1
        elif r.returncode == 1 and first.startswith("load.lua:1: restore: ") and "'mutant.h5'" in first:
            refused += 1
        elif r.returncode == 1 and first.startswith("load.lua:2: cycle: "):
            stopped += 1  # loaded a state nothing in the file contradicts, which the run then refused
        else:
            bad.append(f"mutant {k}: {name} {what}: status {r.returncode}: {r.stderr.strip()[-300:]}")
    print(f"checkpoint_mutants: {count} mutants of {len(names)} datasets: {refused} refused naming the file, "
          f"{loaded} loaded and cycled, {stopped} loaded and stopped by the run with a message, {len(bad)} otherwise")
    for b in bad:
        print("  " + b)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
