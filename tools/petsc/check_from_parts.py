"""The operator assembled from part files against ugo's one-process solve (`make
test-petsc`, after check_parts.py; docs/petsc.md, "The operator from the part files").

For each case below, `ugo solve CASE --part i/n` links every part, `ugo solve CASE --part
i/n --linked …` writes every part's rows, and `tools/petsc/run -n P --from-parts` balances
and solves the operator they make (GMRES to 1e-13); `ugo solve CASE --passes 1` solves the
same linking in one process (GMRES to 1e-13, its kernel saved with the balancing factors):

* the glossy Cornell box's hierarchy (check.py's `HIERARCHY`, 4 cells) in 4 parts, whose
  clusters span parts, on 1 and 2 ranks;
* the opal diffuser (a transmitting panel whose twins lie in different parts) in 2 parts
  on 2 ranks;
* a room lit by a luminaire, whose leaves are split along its light before the solve
  (`cases/office.toml`, coarse), in 2 parts on 2 ranks;

the field equals ugo's to 1e-10 of the largest luminance, and every balancing factor to
1e-10. Refused by name: rows files missing a part, rows files of two cases, a
comparison beyond `--within` (1e-30: the check can fail, and fails on 2 ranks without
hanging the other), part files of another case given to `--linked`, and a rows file of
an older format.

    /usr/bin/python3 tools/petsc/check_from_parts.py [UGO] [WORK_FOLDER]
"""

import os
import shutil
import subprocess
import sys

import h5py

from check import HERE, HIERARCHY, HIERARCHY_SOLUTION, OPAL, ROOT, check, failures, run

OFFICE = ["cases/office.toml", "--root-size", "1", "--patch-size", "0.25"]


def parts(ugo, work, name, case, count):
    """Links and rows of every part of `count` of `case`; the rows files."""
    links = [os.path.join(work, f"{name}-links-{i}.h5") for i in range(count)]
    rows = [os.path.join(work, f"{name}-rows-{i}.h5") for i in range(count)]
    for i, out in enumerate(links):
        run(ugo, "solve", case[0], "--part", f"{i}/{count}", "-o", out, *case[1:])
    for i, out in enumerate(rows):
        run(ugo, "solve", case[0], "--part", f"{i}/{count}", "--linked", *links, "-o", out, *case[1:])
    return links, rows


def one_process(ugo, work, name, case):
    out = os.path.join(work, f"{name}-one.h5")
    run(ugo, "solve", case[0], "--passes", "1", "--method", "gmres", "--tolerance", "1e-13", "--save-kernel", "-o", out, *case[1:])
    return out


def from_parts(work, name, rows, ranks, against):
    """The parts' solve on `ranks` ranks; the largest differences it printed."""
    out = os.path.join(work, f"{name}-parts-{ranks}.h5")
    said = run(os.path.join(HERE, "run"), "-n", str(ranks), "--from-parts", *rows, "-o", out, "--against", against, "--tolerance", "1e-13")
    print(said, end="")
    line = next(l for l in said.splitlines() if "against" in l)
    figures = dict(pair.strip().split(" ")[:2] for pair in line.split(": ", 1)[1].split(" (")[0].split(","))
    return {k: float(v) for k, v in figures.items()}


def refused(command, expected):
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    said = done.stdout + done.stderr
    ok = done.returncode != 0 and expected in said and "Traceback" not in said and "panicked" not in said
    print(f"check_from_parts: refused ({expected}): {'ok' if ok else 'FAILED'}")
    if not ok:
        print(said[-2000:])
        failures.append(f"refusal: {expected}")


def main():
    ugo = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "target/release/ugo"))
    work = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "out/petsc-check"))
    os.makedirs(work, exist_ok=True)
    cases = [("cornell", HIERARCHY, 4, (1, 2)), ("opal", OPAL + ["--kernel", "hierarchical"], 2, (2,)), ("office", OFFICE + ["--kernel", "hierarchical"], 2, (2,))]
    made = {}
    for name, case, count, ranks in cases:
        links, rows = parts(ugo, work, name, case, count)
        one = one_process(ugo, work, name, case)
        made[name] = (links, rows)
        for r in ranks:
            worst = from_parts(work, name, rows, r, one)
            check(f"{name}, {count} parts on {r} ranks: field", worst["field"], HIERARCHY_SOLUTION)
            check(f"{name}, {count} parts on {r} ranks: balancing factors", max(worst["receive"], worst["send"]), HIERARCHY_SOLUTION)
    (cornell_links, cornell_rows), (_, opal_rows) = made["cornell"], made["opal"]
    out = os.path.join(work, "refused.h5")
    refused([os.path.join(HERE, "run"), "--from-parts", *cornell_rows[:3], "-o", out], "give every part of one partition once")
    refused([os.path.join(HERE, "run"), "-n", "2", "--from-parts", cornell_rows[0], opal_rows[1], "-o", out], "were formed for different cases")
    cornell_one = os.path.join(work, "cornell-one.h5")
    refused([os.path.join(HERE, "run"), "-n", "2", "--from-parts", *cornell_rows, "-o", out, "--against", cornell_one, "--within", "1e-30"], "beyond 1e-30")
    refused([ugo, "solve", OPAL[0], "--part", "0/4", "--linked", *cornell_links, "-o", out, *OPAL[1:], "--kernel", "hierarchical"], "was linked for another case")
    old = os.path.join(work, "cornell-rows-format-1.h5")
    shutil.copyfile(cornell_rows[0], old)
    with h5py.File(old, "r+") as f:
        f["rows"].attrs["format"] = 1
    refused([os.path.join(HERE, "run"), "--from-parts", old, *cornell_rows[1:], "-o", out], "rows format 1")
    if failures:
        sys.exit(f"check_from_parts: {len(failures)} failed: {', '.join(failures)}")
    print("check_from_parts: ok")


if __name__ == "__main__":
    main()
