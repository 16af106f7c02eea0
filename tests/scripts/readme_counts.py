#!/usr/bin/env python3
"""The counts tests/README.md states, against the build's tests and the code.

Usage: readme_counts.py README TOTALS_H BUILD_DIR CTEST [--grids TOP_README] [--mutate]

Checks, in README:
  * "`Suite.Name` (N)": N is the number of GoogleTest tests of the core
    (the ctest names Suite.Name that `CTEST -N` lists in BUILD_DIR);
  * every "`PATTERN` (N" whose PATTERN has a `*` (e.g. `stability_*` (34,
    `BoundariesAdd.*` (2)): N is the number of ctest names it matches; a
    pattern that matches no test of this build (a host not built) is
    skipped, and said so;
  * "f_ID[1..N]": N is kOutputSize in TOTALS_H (the length of the fix's
    global vector);
  * every unit test it names (`Suite.Name`, no wildcard) is one of the
    build's;
  * with --grids, TOP_README's "processes on N grids": N (a word) is the
    number of processor grids the identity tests run on (the LAMMPS tests
    that compare their atoms with one process's, same_atoms.sh or
    identical_every_test.sh; grids as `-var procs` or the every test's
    argument give them, the one-process grid and LAMMPS's own choice not
    counted).
Prints one line per count, then "PASS: ..." or "FAIL: ...". --mutate adds
one to the unit test count read from README first: the check's own proof
that it sees a wrong count.
"""
import fnmatch
import json
import re
import subprocess
import sys


def ctest_names(build, ctest):
    out = subprocess.run([ctest, "-N"], cwd=build, capture_output=True, text=True, check=True)
    return re.findall(r"^\s*Test\s+#\d+: (\S+)\s*$", out.stdout, re.M)


WORDS = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
         "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen", "seventeen",
         "eighteen", "nineteen", "twenty"]


def identity_grids(build, ctest):
    """The processor grids of the LAMMPS tests that compare with one process."""
    out = subprocess.run([ctest, "--show-only=json-v1"], cwd=build, capture_output=True,
                         text=True, check=True)
    grids = set()
    for test in json.loads(out.stdout)["tests"]:
        if not test["name"].startswith("lammps_"):
            continue
        command = test.get("command") or []
        env = []
        for prop in test.get("properties", []):
            if prop["name"] == "ENVIRONMENT":
                env = prop["value"]
        every = any(c.endswith("identical_every_test.sh") for c in command)
        if not every and not any("same_atoms.sh" in e for e in env):
            continue
        grid = None
        if every:
            grid = command[4]    # HOST BUILD NP GRID KIND
        elif "procs" in command:
            grid = command[command.index("procs") + 1]
        if grid and "*" not in grid and grid.split() != ["1", "1", "1"]:
            grids.add("x".join(grid.split()))
    return grids


def main(argv):
    mutate = "--mutate" in argv
    args = [a for a in argv[1:] if a != "--mutate"]
    top = None
    if "--grids" in args:
        k = args.index("--grids")
        top = args[k + 1] if k + 1 < len(args) else None
        del args[k:k + 2]
    if len(args) != 4:
        print(__doc__)
        return 2
    readme_path, totals_path, build, ctest = args
    readme = open(readme_path).read()
    names = ctest_names(build, ctest)
    unit = [n for n in names if re.fullmatch(r"[A-Z]\w*\.\w+(/\w+)*", n)]
    size = re.search(r"constexpr\s+int\s+kOutputSize\s*=\s*(\d+)\s*;", open(totals_path).read())
    wrong, checked = [], 0

    def check(what, stated, actual):
        nonlocal checked
        checked += 1
        line = f"{what}: README says {stated}, "
        if stated == actual:
            print(line + "and so it is")
        else:
            print(line + f"there are {actual}")
            wrong.append(what)

    stated_unit = re.search(r"`Suite\.Name` \((\d+)\)", readme)
    stated_output = re.search(r"f_ID\[1\.\.(\d+)\]", readme)
    if not names or not unit or not size or not stated_unit or not stated_output:
        print("FAIL: no tests listed in the build, or no unit test count or f_ID range in the "
              "README, or no kOutputSize in the header")
        return 1
    check("unit tests (`Suite.Name`)", int(stated_unit.group(1)) + (1 if mutate else 0), len(unit))
    check("output vector (f_ID[1..N])", int(stated_output.group(1)), int(size.group(1)))
    for pattern, stated in re.findall(r"`([^`\s]*\*[^`\s]*)` \((\d+)[,:)]", readme):
        matched = [n for n in names if fnmatch.fnmatchcase(n, pattern)]
        if not matched:
            print(f"`{pattern}`: README says {stated}; no test of this build matches: skipped")
            continue
        check(f"`{pattern}`", int(stated), len(matched))
    if top:
        said = re.search(r"processes on (\w+) grids", open(top).read())
        grids = identity_grids(build, ctest)
        print("identity test grids: " + " ".join(sorted(grids)))
        if not grids:
            print(f"{top}'s grids: no LAMMPS identity test in this build: skipped")
        elif not said or said.group(1) not in WORDS:
            print(f"{top}: no \"processes on N grids\" with N a number word")
            wrong.append(f"{top}'s grids")
        else:
            check(f"grids the identity tests compare ({top})", WORDS.index(said.group(1)),
                  len(grids))
    unit_set = set(unit)
    for name in sorted(set(re.findall(r"`([A-Z]\w*\.[A-Z]\w*)`", readme)) - {"Suite.Name"}):
        checked += 1
        if name not in unit_set:
            print(f"`{name}`: README names it, no such unit test")
            wrong.append(f"`{name}`")
    if wrong:
        print(f"FAIL: {len(wrong)} of {checked} counts and names are wrong: "
              + ", ".join(wrong))
        return 1
    print(f"PASS: the {checked} counts and unit test names checked are those of the build and "
          "the code")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
