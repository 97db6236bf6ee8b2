#!/usr/bin/env python3
"""Mutated scripts never crash, hang or run away with memory.

Each mutant is one of the seed scripts with 1 to 6 mutations (seeded, so a run is reproducible):
a number replaced by an extreme or odd one (0, -1, 1e-300, 1e300, 1e12, 0.5, a huge integer),
a line deleted or repeated, two lines swapped, a string replaced, a brace or bracket dropped.
Each runs under a time limit and an address-space limit and is classified: ok (status 0), a
clean error (status 1, the first line of stderr "FILE:LINE: word: ..."), a long run (past the
time limit, its progress lines showing the cycles it was asked for going on), or a failure: a
crash (a signal), a hang (past the time limit with no cycles going on), a memory overrun, an
error that names no line.

    python3 scripts.py EDEM WORKDIR [MUTANTS] [SEED]
"""
import os
import random
import re
import resource
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SEEDS = [os.path.join(ROOT, p) for p in ("scripts/examples/first_model.lua", "scripts/examples/reading_the_model.lua",
                                         "tests/sweep/settle.lua")]
ODD_NUMBERS = ["0", "-1", "1e-300", "1e300", "1e12", "0.5", "-0.0", "9007199254740993", "3", "1e-9", "100000"]
TIME_LIMIT = 60  # s
MEMORY_LIMIT = 2 << 30  # bytes of address space
PROGRESS_EVERY = 10  # s between progress lines
PROGRESS = re.compile(r"^cycle (\d+) \(", re.M)
NUMBER = re.compile(r"(?<![\w.])-?\d+(\.\d+)?([eE][-+]?\d+)?")


def mutate(lines, rng):
    lines = list(lines)
    kind = rng.randrange(6)
    i = rng.randrange(len(lines))
    if kind == 0 or kind == 1:  # a number made odd (twice as likely: most input is numbers)
        numbers = [(k, m) for k, line in enumerate(lines) for m in NUMBER.finditer(line)]
        if numbers:
            k, m = rng.choice(numbers)
            lines[k] = lines[k][:m.start()] + rng.choice(ODD_NUMBERS) + lines[k][m.end():]
    elif kind == 2:
        del lines[i]
    elif kind == 3:
        lines.insert(i, lines[i])
    elif kind == 4:
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    else:
        line = lines[i]
        for old, new in (('"', "'"), ("}", ""), ("{", ""), ("rock", "rok"), ("=", "==")):
            if old in line:
                lines[i] = line.replace(old, new, 1)
                break
    return lines


def cycling_as_asked(output):
    """Whether a run stopped at the time limit was cycling on, as its script asked (cycle(1e12)):
    its progress lines show the cycle count growing."""
    if isinstance(output, bytes):
        output = output.decode(errors="replace")
    cycles = [int(m.group(1)) for m in PROGRESS.finditer(output or "")]
    return len(cycles) >= 2 and cycles[-1] > cycles[0]


def limit_memory():
    # AddressSanitizer reserves terabytes of address space for its shadow memory and cannot start
    # under a limit: under it (the sanitizer build's suite) memory goes unbounded.
    if "ASAN_OPTIONS" not in os.environ:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def main():
    edem, work = os.path.abspath(sys.argv[1]), sys.argv[2]
    count = int(sys.argv[3]) if len(sys.argv) > 3 else 60
    rng = random.Random(int(sys.argv[4]) if len(sys.argv) > 4 else 1)
    os.makedirs(work, exist_ok=True)
    seeds = [open(p).read().split("\n") for p in SEEDS]
    tally = {"ok": 0, "clean error": 0, "long": 0}
    failures = []
    for n in range(count):
        lines = rng.choice(seeds)
        for _ in range(rng.randint(1, 6)):
            lines = mutate(lines, rng)
        name = f"mutant_{n:05d}.lua"
        with open(os.path.join(work, name), "w") as f:
            f.write("\n".join(lines))
        try:
            r = subprocess.run([edem, "--progress", str(PROGRESS_EVERY), "--threads", "1", "run", name], cwd=work,
                               capture_output=True, text=True, errors="replace", timeout=TIME_LIMIT,
                               preexec_fn=limit_memory)
        except subprocess.TimeoutExpired as stopped:
            if cycling_as_asked(stopped.stdout):
                tally["long"] += 1
            else:
                failures.append(f"{name}: hang (over {TIME_LIMIT} s, no cycles going on)")
            continue
        first = r.stderr.split("\n", 1)[0]
        if r.returncode == 0:
            tally["ok"] += 1
        elif r.returncode == 1 and re.match(rf"^{re.escape(name)}:\d+: [a-z_]+: ", first):
            tally["clean error"] += 1
        elif r.returncode == 1 and ("out of memory" in r.stderr or "std::bad_alloc" in r.stderr):
            failures.append(f"{name}: memory over {MEMORY_LIMIT >> 30} GB: {first[:200]}")
        elif r.returncode < 0:
            failures.append(f"{name}: crash (signal {-r.returncode}): {r.stderr.strip()[-200:]}")
        else:
            failures.append(f"{name}: status {r.returncode}, no line named: {first[:200]}")
    print(f"fuzz scripts: {count} mutants of {len(SEEDS)} scripts: {tally['ok']} ran, {tally['clean error']} "
          f"stopped with an error naming their line, {tally['long']} were still cycling as asked at {TIME_LIMIT} s, "
          f"{len(failures)} otherwise")
    for f in failures:
        print("  " + f)
    sys.exit(1 if failures else 0)


main()
